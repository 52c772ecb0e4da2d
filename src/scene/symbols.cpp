// The scene parser's symbol tables: looking names up, #declare and #local, and the values
// identifiers and array elements stand for.
#include <algorithm>

#include "scene/scene_parser.h"
#include "util/format.h"

namespace mirage::scene_detail {
namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON

// What a value holds: its objects (shapes, unions, lights) and array elements, and how deeply
// they nest.
struct Weight {
    std::size_t objects = 0, elements = 0;
    int depth = 0;
};

void weigh_object(const ObjectNode& object, int depth, Weight& w) {
    ++w.objects;
    w.depth = std::max(w.depth, depth);
    for (const ObjectNode& child : object.children) weigh_object(child, depth + 1, w);
}

void weigh(const Value& value, int depth, Weight& w) {
    if (const auto* object = value.get_if<ObjectNode>()) {
        weigh_object(*object, depth, w);
    } else if (const auto* array = value.get_if<ArrayValue>()) {
        w.elements += array->elements.size();
        w.depth = std::max(w.depth, depth);
        for (const auto& e : array->elements) {
            if (e) weigh(*e, depth + 1, w);
        }
    }
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Symbols

std::shared_ptr<Symbol> SceneParser::lookup(const std::string& name, int* depth) const {
    for (std::size_t i = tables_.size(); i-- > 0;) {
        auto it = tables_[i].find(name);
        if (it != tables_[i].end()) {
            if (depth) *depth = static_cast<int>(i);
            return it->second;
        }
    }
    return nullptr;
}

void SceneParser::declare(const Token& name_token, Value value, bool local, std::size_t scope) {
    const std::string& name = name_token.text();
    if (local) {
        auto& table = scope > 0 && scope <= tables_.size() ? tables_[scope - 1] : tables_.back();
        auto it = table.find(name);
        if (it != table.end()) {
            it->second->value = std::move(value);
            it->second->loc = name_token.loc();
            return;
        }
        table[name] = std::make_shared<Symbol>(Symbol{std::move(value), name_token.loc()});
        return;
    }
    // #declare changes the identifier where it is visible, else creates a global one.
    if (auto sym = lookup(name)) {
        sym->value = std::move(value);
        sym->loc = name_token.loc();
        return;
    }
    tables_[0][name] = std::make_shared<Symbol>(Symbol{std::move(value), name_token.loc()});
}

// ---------------------------------------------------------------------------------------
// Identifier values and array elements

const Value* SceneParser::peek_identifier_value(std::size_t ahead) {
    const Token& t = peek(ahead);
    if (!is_identifier(t)) return nullptr;
    std::shared_ptr<Symbol> sym = t.symbol ? t.symbol : lookup(t.text());
    if (!sym) return nullptr;
    if (auto* a = sym->value.get_if<ArrayValue>()) {
        if (peek_array_index(ahead + 1)) {
            // The first element assigned stands for the type of the array's elements.
            for (const auto& e : a->elements) {
                if (e) return e.get();
            }
            return nullptr;
        }
    }
    return &use_value(t, *sym, sym->value);
}

std::shared_ptr<Value>& SceneParser::index_array(ArrayValue& array, const Token& name) {
    std::size_t index = 0;
    for (std::size_t d = 0; d < array.sizes.size(); ++d) {
        Token open = expect_punct("[", "for an index of the array '" + name.text() + "'");
        double v = parse_float();
        if (!(v >= -kEpsilon && v + kEpsilon < array.sizes[d])) {
            fail(open, "index " + shortest(v) + " of the array '" + name.text() +
                           "' is out of range 0 to " + std::to_string(array.sizes[d] - 1));
        }
        const int k = static_cast<int>(v + kEpsilon);
        index = index * static_cast<std::size_t>(array.sizes[d]) + static_cast<std::size_t>(k);
        expect_punct("]", "after an array index");
    }
    return array.elements[index];
}

Value SceneParser::identifier_value(const Token& name) {
    std::shared_ptr<Symbol> sym = name.symbol ? name.symbol : lookup(name.text());
    if (!sym) fail(name, "undefined identifier '" + name.text() + "'");
    const Value* value = &sym->value;
    if (auto* a = sym->value.get_if<ArrayValue>()) {
        if (peek_array_index()) {
            Token at = peek(0);
            std::shared_ptr<Value>& e = index_array(*a, name);
            if (!e) fail(at, "element of the array '" + name.text() + "' used before it is set");
            value = e.get();
        }
    }
    value = &use_value(name, *sym, *value);  // an opaque value's use fails here
    // A copy costs what it holds: objects and array elements count towards the limits, and
    // nothing nests deeper than the parser itself could (a #declare A[0] = A; in a loop would).
    Weight w;
    weigh(*value, 1, w);
    if (w.depth > options_.limits.max_nesting) {
        fail_fatal(name, "'" + name.text() + "' holds objects or arrays nested more than " +
                             std::to_string(options_.limits.max_nesting) + " deep, mirage's limit");
    }
    count_objects(w.objects, name);
    count_array_elements(w.elements, name);
    return deep_copy(*value);
}

}  // namespace mirage::scene_detail

// The scene parser's symbol tables: looking names up, #declare and #local, and the values
// identifiers and array elements stand for.
#include "scene/scene_parser.h"

namespace mirage::scene_detail {
namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON

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

void SceneParser::declare(const Token& name_token, Value value, bool local) {
    const std::string& name = name_token.text();
    if (local) {
        auto& table = tables_.back();
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
    if (auto* a = std::get_if<ArrayValue>(&sym->value.data)) {
        if (peek_array_index(ahead + 1)) {
            // The first element assigned stands for the type of the array's elements.
            for (const auto& e : a->elements) {
                if (e) return e.get();
            }
            return nullptr;
        }
    }
    return &sym->value;
}

std::shared_ptr<Value>& SceneParser::index_array(ArrayValue& array, const Token& name) {
    std::size_t index = 0;
    for (std::size_t d = 0; d < array.sizes.size(); ++d) {
        Token open = expect_punct("[", "for an index of the array '" + name.text() + "'");
        double v = parse_float();
        int k = static_cast<int>(v + kEpsilon);
        if (v < -kEpsilon || k < 0 || k >= array.sizes[d]) {
            fail(open, "index " + format_str(v, 0, -1) + " of the array '" + name.text() +
                           "' is out of range 0 to " + std::to_string(array.sizes[d] - 1));
        }
        index = index * static_cast<std::size_t>(array.sizes[d]) + static_cast<std::size_t>(k);
        expect_punct("]", "after an array index");
    }
    return array.elements[index];
}

Value SceneParser::identifier_value(const Token& name) {
    std::shared_ptr<Symbol> sym = name.symbol ? name.symbol : lookup(name.text());
    if (!sym) fail(name, "undefined identifier '" + name.text() + "'");
    if (auto* a = std::get_if<ArrayValue>(&sym->value.data)) {
        if (peek_array_index()) {
            Token at = peek(0);
            std::shared_ptr<Value>& e = index_array(*a, name);
            if (!e) fail(at, "element of the array '" + name.text() + "' used before it is set");
            return deep_copy(*e);
        }
    }
    return deep_copy(sym->value);
}

}  // namespace mirage::scene_detail

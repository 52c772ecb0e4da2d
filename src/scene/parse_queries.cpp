// The functions of the scene language that ask an object a question while the scene is
// parsed: trace(), inside(), min_extent() and max_extent() (POV-Ray's Parse_Trace and
// Parse_Inside), answered by the tracer's intersection code.
#include "scene/scene_parser.h"
#include "trace/object_query.h"

namespace mirage::scene_detail {

Numeric SceneParser::parse_object_function(const Token& name) {
    const std::string& f = name.text();
    expect_punct("(", "after '" + f + "'");
    Token object_token = peek(0);
    if (!starts_object(object_token) || !is_identifier(object_token)) {
        fail(object_token,
             "expected an object identifier in '" + f + "', got " + describe(object_token));
    }
    Token id = next();
    Value v = identifier_value(id);
    const auto* object = std::get_if<ObjectNode>(&v.data);
    if (!object) fail(id, "expected an object, got " + value_type_name(v));
    if (f == "min_extent" || f == "max_extent") {
        expect_punct(")", "after the object of '" + f + "'");
        auto box = object_extent(*object);
        if (!box) fail(name, box.message());
        if (box->empty()) return Numeric::vector3(glm::dvec3(0.0));
        return Numeric::vector3(f == "min_extent" ? box->lo : box->hi);
    }
    accept_comma();
    const glm::dvec3 a = parse_vector();
    if (f == "inside") {
        expect_punct(")", "after the arguments of 'inside'");
        auto in = point_inside_object(*object, a);
        if (!in) fail(name, in.message());
        return Numeric::scalar(*in ? 1.0 : 0.0);
    }
    accept_comma();
    const glm::dvec3 direction = parse_vector();
    auto hit = trace_object(*object, a, direction);
    if (!hit) fail(name, hit.message());
    const glm::dvec3 point = *hit ? (*hit)->point : glm::dvec3(0.0);
    const glm::dvec3 normal = *hit ? (*hit)->normal : glm::dvec3(0.0);
    // An optional vector identifier receives the normal (<0, 0, 0> without a hit).
    accept_comma();
    if (is_identifier(peek(0)) && !peek_punct(")")) {
        Token normal_name = next();
        auto sym = normal_name.symbol ? normal_name.symbol : lookup(normal_name.text());
        if (!sym) fail(normal_name, "undefined identifier '" + normal_name.text() + "'");
        sym->value.data = Numeric::vector3(normal);
    }
    expect_punct(")", "after the arguments of 'trace'");
    return Numeric::vector3(point);
}

}  // namespace mirage::scene_detail

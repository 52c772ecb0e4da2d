// The functions of the scene language that ask an object a question while the scene is
// parsed: trace(), inside(), min_extent() and max_extent() (POV-Ray's Parse_Trace and
// Parse_Inside), answered by the tracer's intersection code.
#include "scene/object_queries.h"
#include "scene/scene_parser.h"

namespace mirage::scene_detail {

Numeric SceneParser::parse_object_function(const Token& name) {
    const std::string& f = name.text();
    expect_punct("(", "after '" + f + "'");
    Token object_token = peek(0);
    if (!starts_object(object_token) || !is_identifier(object_token)) {
        fail(object_token,
             "expected an object identifier in '" + f + "', got " + describe(object_token));
    }
    const ObjectQueries& queries = options_.object_queries;
    if (!queries.trace || !queries.inside || !queries.extent) {
        fail(name, "'" + f +
                       "' asks the tracer about an object, and this parse has no tracer "
                       "to ask (ParseOptions::object_queries)");
    }
    Token id = next();
    Value v = identifier_value(id);
    const auto* object = v.get_if<ObjectNode>();
    if (!object) fail(id, "expected an object, got " + value_type_name(v));
    if (f == "min_extent" || f == "max_extent") {
        expect_punct(")", "after the object of '" + f + "'");
        auto box = queries.extent(*object);
        if (!box) fail(name, box.message());
        if (!*box) return Numeric::vector3(glm::dvec3(0.0));
        return Numeric::vector3(f == "min_extent" ? (*box)->first : (*box)->second);
    }
    accept_comma();
    const glm::dvec3 a = parse_vector();
    if (f == "inside") {
        expect_punct(")", "after the arguments of 'inside'");
        auto in = queries.inside(*object, a);
        if (!in) fail(name, in.message());
        return Numeric::scalar(*in ? 1.0 : 0.0);
    }
    accept_comma();
    const glm::dvec3 direction = parse_vector();
    auto hit = queries.trace(*object, a, direction);
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

// The values of the scene language: what an expression yields and an identifier holds.
// Numbers follow POV-Ray's expression model: a float, a 2-, 3- or 4-component vector or a
// 5-component colour (rgbft), all held as up to five doubles.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "scene/camera.h"
#include "scene/function.h"
#include "scene/lexer.h"
#include "scene/material_value.h"
#include "scene/object_tree.h"
#include "scene/scene.h"

namespace mirage {

/// A float (size 1), a vector (size 2 to 4) or a colour (size 5).
struct Numeric {
    int size = 1;
    std::array<double, 5> v{};

    static Numeric scalar(double x);
    static Numeric vector3(const glm::dvec3& p);
    static Numeric colour(const Colour& c);
    glm::dvec3 xyz() const { return glm::dvec3(v[0], v[1], v[2]); }
};

/// POV-Ray's Promote_Express: widens to `size` components, repeating a float and padding a
/// vector with zeros; never narrows.
Numeric promote(const Numeric& n, int size);

/// The colour of a 5-component numeric (rgb, filter, transmit).
Colour numeric_to_colour(const Numeric& n);

/// "float", "vector", "colour"... for messages.
std::string numeric_type_name(int size);

/// A macro: its parameters and where its body lies (token indices in its file, the body ends
/// at the `#` of its `#end`).
struct MacroDef {
    std::string name;
    std::vector<std::string> parameters;
    std::shared_ptr<const SourceFile> file;
    std::size_t body_begin = 0;
    std::size_t body_end = 0;
    FileLoc loc;
};

struct Value;

/// An array; elements stay empty until assigned.
struct ArrayValue {
    std::vector<int> sizes;
    std::vector<std::shared_ptr<Value>> elements;
};

struct ColourMapValue {
    std::vector<ColourMapEntry> entries;
};

/// A value the parser keeps without evaluating it, where POV-Ray would: something outside the
/// supported subset (a function, a normal, a pigment pattern mirage does not know...) or a
/// declaration the parser could not read.  Declaring and copying it is always fine, so that a
/// standard include file's unused declarations cost nothing; only a use is an error, at the
/// use, naming the reason.  In lenient mode a use of an opaque texture, pigment, finish,
/// colour map, transform or sky_sphere takes its kind's default instead (what the compiler
/// does not need) and an opaque object becomes an unknown object (ObjectNode::Kind::Empty).
///
/// Plug-in point: a part of the parser that meets something it cannot evaluate calls
/// SceneParser::unsupported(); inside a #declare that turns the declared value into an
/// OpaqueValue of the declaration's kind with that reason.
struct OpaqueValue {
    std::string what;    // the kind of value, as value_type_name names it ("pigment", "object",
                         // "function", "normal"...), "value" when not known
    std::string reason;  // why it is opaque ("unsupported pigment pattern 'marble'"); empty for
                         // a kind mirage never evaluates
    FileLoc loc;         // where the reason lies (empty with the reason)
};

/// A value of the heap held by a scene value: its large alternatives (objects, textures,
/// pigments, materials, the sky) would otherwise make every value, and every frame of the
/// parser that holds one, as large as the largest (7.3 KB).  Copies are deep; a moved-from
/// box is empty and may only be assigned or destroyed.  Made implicitly from a T, as the
/// variant's other alternatives are from theirs.
template <class T>
class Boxed {
  public:
    Boxed(const T& v) : p_(std::make_unique<T>(v)) {}        // NOLINT(google-explicit-constructor)
    Boxed(T&& v) : p_(std::make_unique<T>(std::move(v))) {}  // NOLINT(google-explicit-constructor)
    Boxed(const Boxed& o) : p_(std::make_unique<T>(*o.p_)) {}
    Boxed(Boxed&&) noexcept = default;
    Boxed& operator=(const Boxed& o) {
        if (this != &o) p_ = std::make_unique<T>(*o.p_);
        return *this;
    }
    Boxed& operator=(Boxed&&) noexcept = default;
    T& operator*() { return *p_; }
    const T& operator*() const { return *p_; }

  private:
    std::unique_ptr<T> p_;
};

namespace value_detail {
/// The alternatives a Value holds boxed, and how it stores a T.
template <class T>
inline constexpr bool kBoxed =
    std::is_same_v<T, ObjectNode> || std::is_same_v<T, Texture> || std::is_same_v<T, Pigment> ||
    std::is_same_v<T, SkySphere> || std::is_same_v<T, MaterialValue>;
template <class T>
using Stored = std::conditional_t<kBoxed<T>, Boxed<T>, T>;
}  // namespace value_detail

struct Value {
    // Boxed or not as value_detail::kBoxed says.
    std::variant<Numeric, std::string, value_detail::Stored<ObjectNode>,
                 value_detail::Stored<Texture>, value_detail::Stored<Pigment>, Finish, Transform,
                 ColourMapValue, CameraState, ArrayValue, std::shared_ptr<const MacroDef>,
                 OpaqueValue, value_detail::Stored<SkySphere>, value_detail::Stored<MaterialValue>,
                 std::shared_ptr<const FunctionCode>>
        data;

    /// Whether the value is a T, and the T it holds (nullptr if it is not one, or throws
    /// std::bad_variant_access for get), whether or not T is boxed.
    template <class T>
    bool holds() const {
        return std::holds_alternative<value_detail::Stored<T>>(data);
    }
    template <class T>
    T* get_if() {
        return unbox<T>(std::get_if<value_detail::Stored<T>>(&data));
    }
    template <class T>
    const T* get_if() const {
        return unbox<T>(std::get_if<value_detail::Stored<T>>(&data));
    }
    template <class T>
    T& get() {
        return *unbox<T>(&std::get<value_detail::Stored<T>>(data));
    }
    template <class T>
    const T& get() const {
        return *unbox<T>(&std::get<value_detail::Stored<T>>(data));
    }

  private:
    template <class T, class S>
    static auto unbox(S* s) {
        using R = std::conditional_t<std::is_const_v<S>, const T, T>;
        if constexpr (std::is_same_v<std::remove_const_t<S>, T>) {
            return static_cast<R*>(s);
        } else {
            return s ? static_cast<R*>(&**s) : static_cast<R*>(nullptr);
        }
    }
};

/// A copy that shares nothing with `value` (array elements are copied too).
Value deep_copy(const Value& value);

/// "float", "vector", "string", "object", "texture"... for messages.
std::string value_type_name(const Value& value);

}  // namespace mirage

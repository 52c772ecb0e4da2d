// Result<T>: a value or an error message, for library code that must not exit.
#pragma once

#include <string>
#include <utility>
#include <variant>

#include "util/file_loc.h"

namespace mirage {

/// An error carried back to the caller; `message` is complete and user-facing
/// (it names the file, line and column, the flag or the value at fault).
struct Error {
    std::string message;
};

/// Either a T or an Error, in the manner of std::expected (which clang-tidy 14 cannot parse).
template <class T>
class [[nodiscard]] Result {
  public:
    Result(T value) : data_(std::move(value)) {}      // NOLINT(google-explicit-constructor)
    Result(Error error) : data_(std::move(error)) {}  // NOLINT(google-explicit-constructor)

    bool ok() const { return data_.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { return std::get<0>(data_); }
    const T& value() const& { return std::get<0>(data_); }
    T&& value() && { return std::get<0>(std::move(data_)); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }

    const Error& error() const { return std::get<1>(data_); }
    const std::string& message() const { return error().message; }

  private:
    std::variant<T, Error> data_;
};

/// Result of an operation that yields nothing but may fail.
struct Ok {};
using Status = Result<Ok>;

inline Error make_error(std::string message) { return Error{std::move(message)}; }

/// An error about the place `loc`: "file:line:column: message" (the message alone when
/// `loc` has no file).
inline Error make_error(const FileLoc& loc, const std::string& message) {
    return Error{place_prefix(loc) + message};
}

}  // namespace mirage

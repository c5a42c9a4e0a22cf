// Errors for bad input: a message that names the problem and where it is (file:line:column and the
// field), returned as a value. Programmer errors use LUXEL_CHECK (check.h) instead.
#pragma once

#include <string>
#include <utility>
#include <variant>

#include "luxel/core/check.h"

namespace luxel {

// Where in an input a problem is. Every part is optional; empty parts are left out of the message.
struct SourceLocation {
    std::string file;   // path of the input file, or a name such as "<string>"
    int line = 0;       // 1-based; 0 = unknown
    int column = 0;     // 1-based; 0 = unknown
    std::string field;  // e.g. "shapes[2].radius"

    // "file:line:column: field" with the unknown parts left out.
    std::string describe() const;
};

// A bad-input error: one line meant for a user.
class Error {
  public:
    explicit Error(std::string message) : message_(std::move(message)) {}
    Error(const SourceLocation& where, const std::string& message);

    const std::string& message() const { return message_; }

  private:
    std::string message_;
};

// Either a value or an Error. The library returns this for anything that depends on user input.
template <typename T>
class [[nodiscard]] Result {
  public:
    Result(T value) : state_(std::in_place_index<0>, std::move(value)) {}
    Result(Error error) : state_(std::in_place_index<1>, std::move(error)) {}

    bool ok() const { return state_.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & {
        LUXEL_CHECK(ok());
        return std::get<0>(state_);
    }
    const T& value() const& {
        LUXEL_CHECK(ok());
        return std::get<0>(state_);
    }
    T&& value() && {
        LUXEL_CHECK(ok());
        return std::get<0>(std::move(state_));
    }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const {
        LUXEL_CHECK(!ok());
        return std::get<1>(state_);
    }

  private:
    std::variant<T, Error> state_;
};

// Result for operations that produce nothing but may fail.
struct Ok {};
using Status = Result<Ok>;

}  // namespace luxel

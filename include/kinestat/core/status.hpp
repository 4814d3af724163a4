// Recoverable failures are returned, not thrown (as in Ceres): a status code plus a message that
// names the item at fault and what to do about it.
//
// Both types are [[nodiscard]]: a function that returns one warns when its result is dropped
// (-Werror makes that a build failure). Drop one only where ignoring it is right, with a comment.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace kinestat {

enum class StatusCode {
  kOk = 0,
  kInvalidInput,  // a model, mesh or option the user must fix (CLI exit status 2)
  kSingular,      // the structure is a mechanism at this posture: some motion is free
  kNotConverged,  // an iterative method stopped before its tolerance
  kInternal,      // a library failure (out of memory in CHOLMOD, ...)
};

// "kInvalidInput", ...: the enumerator's name, for messages about the status itself.
const char* status_code_name(StatusCode code);

class [[nodiscard]] Status {
 public:
  Status() = default;
  Status(StatusCode code, std::string message) : code_(code), message_(std::move(message)) {}

  static Status Ok() { return {}; }
  static Status Invalid(std::string m) { return {StatusCode::kInvalidInput, std::move(m)}; }
  static Status Singular(std::string m) { return {StatusCode::kSingular, std::move(m)}; }
  static Status NotConverged(std::string m) { return {StatusCode::kNotConverged, std::move(m)}; }
  static Status Internal(std::string m) { return {StatusCode::kInternal, std::move(m)}; }

  bool ok() const { return code_ == StatusCode::kOk; }
  StatusCode code() const { return code_; }
  const std::string& message() const { return message_; }

 private:
  StatusCode code_ = StatusCode::kOk;
  std::string message_;
};

namespace detail {
// Prints "kinestat: StatusOr::value() called on an error (CODE: MESSAGE)..." to stderr and aborts.
[[noreturn]] void status_or_value_of_error(const Status& status);
}  // namespace detail

// A value or the reason there is none.
//
// Reading the value (value(), *, ->) of a StatusOr that holds an error is a programming error, not
// bad input: the caller must test ok() first. It prints the status to stderr and aborts (in every
// build type), instead of handing out a value that was never computed. Bad input itself never
// aborts: it is the error status the caller tests for.
//
// A StatusOr made from Status::Ok() (a status without a value) holds kInternal instead, so that
// ok() is true exactly when there is a value.
template <class T>
class [[nodiscard]] StatusOr {
 public:
  StatusOr(T value) : value_(std::move(value)) {}         // NOLINT: implicit by design
  StatusOr(Status status) : status_(std::move(status)) {  // NOLINT
    if (status_.ok()) status_ = Status::Internal("StatusOr made from an OK status without a value");
  }
  bool ok() const { return status_.ok(); }
  const Status& status() const { return status_; }
  const T& value() const& { return checked(); }
  T& value() & { return checked(); }
  T&& value() && { return std::move(checked()); }
  const T& operator*() const& { return checked(); }
  T& operator*() & { return checked(); }
  T&& operator*() && { return std::move(checked()); }
  const T* operator->() const { return &checked(); }
  T* operator->() { return &checked(); }

 private:
  const T& checked() const {
    if (!value_) detail::status_or_value_of_error(status_);
    return *value_;
  }
  T& checked() {
    if (!value_) detail::status_or_value_of_error(status_);
    return *value_;
  }

  Status status_;
  std::optional<T> value_;
};

}  // namespace kinestat

// Recoverable failures are returned, not thrown (as in Ceres): a status code plus a message that
// names the item at fault and what to do about it.
#pragma once

#include <string>
#include <utility>

namespace kinestat {

enum class StatusCode {
  kOk = 0,
  kInvalidInput,   // a model, mesh or option the user must fix (CLI exit status 2)
  kSingular,       // the structure is a mechanism at this posture: some motion is free
  kNotConverged,   // an iterative method stopped before its tolerance
  kInternal,       // a library failure (out of memory in CHOLMOD, ...)
};

class Status {
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

// A value or the reason there is none.
template <class T>
class StatusOr {
 public:
  StatusOr(T value) : value_(std::move(value)) {}  // NOLINT: implicit by design
  StatusOr(Status status) : status_(std::move(status)) {}  // NOLINT
  bool ok() const { return status_.ok(); }
  const Status& status() const { return status_; }
  const T& value() const& { return value_; }
  T& value() & { return value_; }
  T&& value() && { return std::move(value_); }
  const T& operator*() const& { return value_; }
  T& operator*() & { return value_; }
  const T* operator->() const { return &value_; }
  T* operator->() { return &value_; }

 private:
  Status status_;
  T value_{};
};

}  // namespace kinestat

#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <variant>

#include <collido/assert.h>

namespace collido {

/// Why an operation did not succeed; the values match CollidoStatusCode across the plugin ABI.
enum class StatusCode : std::int32_t {
  kOk = 0,
  kUnsupported = 1,      ///< the backend cannot answer this; never a wrong answer instead
  kInvalidArgument = 2,  ///< malformed input (sizes, options, non-finite values, bad files)
  kInvalidHandle = 3,    ///< unknown, released or stale model handle
  kEngineFailure = 4,    ///< the engine threw or reported an error
  kOutOfMemory = 5,
  kInternal = 6,  ///< a bug
};

/// Short lower-case name of a status code ("unsupported", ...).
const char* statusCodeName(StatusCode code);

/// Outcome of an operation: a code and, when not ok, a message naming what went wrong.
class [[nodiscard]] Status {
 public:
  /// The ok status.
  Status() = default;
  /// A failure; `message` names the file/field/object and the problem.
  Status(StatusCode code, std::string message) : code_(code), message_(std::move(message)) {}

  bool ok() const { return code_ == StatusCode::kOk; }
  StatusCode code() const { return code_; }
  const std::string& message() const { return message_; }
  /// "unsupported: <message>" style text for people.
  std::string toString() const;

 private:
  StatusCode code_ = StatusCode::kOk;
  std::string message_;
};

/// A value or the Status that explains why there is none.
template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : state_(std::move(value)) {}        // NOLINT(google-explicit-constructor)
  Result(Status status) : state_(std::move(status)) {  // NOLINT(google-explicit-constructor)
    COLLIDO_ASSERT(!std::get<Status>(state_).ok(), "a Result without a value needs a failure");
  }

  bool ok() const { return std::holds_alternative<T>(state_); }
  /// The failure; only valid when !ok().
  const Status& status() const {
    COLLIDO_ASSERT(!ok(), "status() of a Result that holds a value");
    return std::get<Status>(state_);
  }
  T& value() & {
    COLLIDO_ASSERT(ok(), "value() of a failed Result");
    return std::get<T>(state_);
  }
  const T& value() const& {
    COLLIDO_ASSERT(ok(), "value() of a failed Result");
    return std::get<T>(state_);
  }
  T&& value() && {
    COLLIDO_ASSERT(ok(), "value() of a failed Result");
    return std::get<T>(std::move(state_));
  }

 private:
  std::variant<T, Status> state_;
};

}  // namespace collido

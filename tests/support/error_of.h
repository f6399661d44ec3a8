#pragma once
// Test helpers for error messages: error_of(f) is the message of the Error that f throws (""
// and a test failure when it throws none); EXPECT_ERROR(expr, substring) checks that expr
// throws an Error whose message contains substring.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "slicereuse/util/error.h"

namespace slicereuse::test {

inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no Error thrown";
  return "";
}

}  // namespace slicereuse::test

#define EXPECT_ERROR(expr, substring)                                                   \
  do {                                                                                  \
    const std::string message_ = ::slicereuse::test::error_of([&] { (void)(expr); });  \
    EXPECT_NE(message_.find(substring), std::string::npos)                              \
        << "message: " << message_ << "\nexpected to contain: " << substring;           \
  } while (0)

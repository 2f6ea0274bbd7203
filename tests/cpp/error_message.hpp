// The message of the vistrack::Error a call throws, for tests that check an error names its field.
#pragma once

#include <string>
#include <utility>

#include "vistrack/error.hpp"

namespace vistrack::testing {

// e.what() of the Error that call() throws; "no error" when it returns (so find() on a field
// name fails the test); any other exception propagates to GoogleTest.
template <class Call>
std::string error_message(Call&& call) {
  try {
    std::forward<Call>(call)();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace vistrack::testing

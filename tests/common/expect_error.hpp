// expect_error: the "call, expect a throw, check the type and what()" pattern of the
// tests, in one place. Host C++ only (no gdel headers), so both the CPU tests and the
// .cu GPU tests can include it.
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <initializer_list>
#include <optional>
#include <source_location>
#include <string>
#include <string_view>

namespace gdel::test {

// Runs fn and expects it to throw E (or a class derived from it) whose what() contains
// every one of parts. Each miss is a non-fatal failure at the caller's line: nothing
// thrown, another exception type (its what() is reported, so the cause is not lost), or
// a part missing from what(). what_for names the case in the "nothing thrown" message.
// Returns the caught exception (sliced to E) so a caller can check its fields too
// (OutOfDeviceMemory::needed); empty when nothing or something else was thrown.
template <class E, class F>
std::optional<E> expect_error(F&& fn, std::initializer_list<std::string_view> parts, std::string_view what_for = {},
                              std::source_location where = std::source_location::current()) {
  // "gdel::InvalidInput mentioning 'a', 'b'", for the failure messages
  std::string wanted = ::testing::internal::GetTypeName<E>();
  const char* sep = " mentioning '";
  for (std::string_view p : parts) {
    wanted.append(sep).append(p) += '\'';
    sep = ", '";
  }
  try {
    fn();
  } catch (const E& e) {
    const std::string_view msg = e.what();
    for (std::string_view p : parts) {
      if (msg.find(p) == std::string_view::npos) {
        ADD_FAILURE_AT(where.file_name(), where.line()) << "message: " << msg << "\nlacks: " << p;
      }
    }
    return e;
  } catch (const std::exception& e) {
    ADD_FAILURE_AT(where.file_name(), where.line())
        << "wrong exception type; expected " << wanted << ", got: " << e.what();
    return std::nullopt;
  }
  ADD_FAILURE_AT(where.file_name(), where.line())
      << (what_for.empty() ? "" : std::string(what_for) + ": ") << "no exception; expected " << wanted;
  return std::nullopt;
}

}  // namespace gdel::test

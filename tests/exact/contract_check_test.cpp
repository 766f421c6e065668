// KMR_CHECK (exact/error.hpp): a failing check throws ContractError whose text is exactly
// "FILE:LINE: message" (file and line of the check site, as before the failing side moved out of
// line into detail::contract_failure); a passing check throws nothing, evaluates its condition
// exactly once and never builds its message. Expectations are spelled out here, not taken from
// error.cpp.
#include <gtest/gtest.h>

#include <string>

#include "exact/error.hpp"

namespace {

// The text a ContractError of the check on line `line` of this file with message `msg` must carry.
std::string expected(int line, const std::string& msg) {
  return std::string(__FILE__) + ":" + std::to_string(line) + ": " + msg;
}

// The what() of the ContractError f throws; fails the test if f throws nothing or something else.
template <class F>
std::string contract_message(F&& f) {
  try {
    f();
  } catch (const kmr::ContractError& e) {
    return e.what();
  } catch (...) {
    ADD_FAILURE() << "threw something other than ContractError";
    return "<other exception>";
  }
  ADD_FAILURE() << "threw nothing";
  return "<no exception>";
}

TEST(ContractCheck, FailingCheckWithLiteralNamesFileLineAndMessage) {
  int line = 0;
  std::string what = contract_message([&] {
    line = __LINE__ + 1;
    KMR_CHECK(1 + 1 == 3, "arithmetic is broken");
  });
  EXPECT_EQ(what, expected(line, "arithmetic is broken"));
  EXPECT_NE(what.find("contract_check_test.cpp:"), std::string::npos);
}

TEST(ContractCheck, FailingCheckWithStringExpressionMessage) {
  int line = 0;
  int k = 41;
  std::string what = contract_message([&] {
    line = __LINE__ + 1;
    KMR_CHECK(k == 42, "k is " + std::to_string(k) + ", not 42");
  });
  EXPECT_EQ(what, expected(line, "k is 41, not 42"));
}

TEST(ContractCheck, ContractErrorIsALogicErrorNotAnInputError) {
  bool logic = false;
  try {
    KMR_CHECK(false, "x");
  } catch (const kmr::InputError&) {
    ADD_FAILURE() << "a contract check must not look like bad input";
  } catch (const std::logic_error&) {
    logic = true;
  }
  EXPECT_TRUE(logic);
}

TEST(ContractCheck, PassingCheckEvaluatesConditionOnceAndNeverItsMessage) {
  int conditions = 0;
  int messages = 0;
  auto cond = [&] { ++conditions; return true; };
  auto msg = [&] { ++messages; return std::string("never built"); };
  EXPECT_NO_THROW(KMR_CHECK(cond(), msg()));
  EXPECT_EQ(conditions, 1);
  EXPECT_EQ(messages, 0);
}

TEST(ContractCheck, FailingCheckEvaluatesConditionAndMessageOnce) {
  int conditions = 0;
  int messages = 0;
  auto cond = [&] { ++conditions; return false; };
  auto msg = [&] { ++messages; return std::string("built once"); };
  int line = 0;
  std::string what = contract_message([&] {
    line = __LINE__ + 1;
    KMR_CHECK(cond(), msg());
  });
  EXPECT_EQ(what, expected(line, "built once"));
  EXPECT_EQ(conditions, 1);
  EXPECT_EQ(messages, 1);
}

// One statement: an `if` without braces around a check keeps its own `else` (no dangling else).
TEST(ContractCheck, IsOneStatement) {
  int taken = 0;
  bool guard = false;
  if (guard)
    KMR_CHECK(false, "not reached");
  else
    taken = 1;
  EXPECT_EQ(taken, 1);
}

}  // namespace

#pragma once
// The error types every layer of kmr throws. Guarantees:
//  * InputError: the caller gave a value kmr refuses (malformed, out of range, degenerate where the
//    contract forbids it). Its message names the value; the CLI turns it into exit status 2.
//  * ContractError: kmr itself broke an invariant. Never expected; always a bug worth a report.
#include <stdexcept>
#include <string>

namespace kmr {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ContractError : std::logic_error {
  using std::logic_error::logic_error;
};

namespace detail {
// The failing side of KMR_CHECK, out of line and cold: throws ContractError("FILE:LINE: msg").
// One call per check site keeps the message formatting (and its branches) out of the caller.
[[noreturn, gnu::cold]] void contract_failure(const char* file, int line, const char* msg);
[[noreturn, gnu::cold]] void contract_failure(const char* file, int line, const std::string& msg);
}  // namespace detail

// KMR_CHECK(cond, msg): a contract check that stays on in every build type. `cond` is evaluated
// once; `msg` (a string literal or a std::string expression) only when `cond` fails.
#define KMR_CHECK(cond, msg)                                                       \
  do {                                                                             \
    if (!(cond)) [[unlikely]]                                                      \
      ::kmr::detail::contract_failure(__FILE__, __LINE__, (msg));                 \
  } while (0)

}  // namespace kmr

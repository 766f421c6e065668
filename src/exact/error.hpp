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

// KMR_CHECK(cond, msg): a contract check that stays on in every build type.
#define KMR_CHECK(cond, msg)                                                              \
  do {                                                                                    \
    if (!(cond))                                                                          \
      throw ::kmr::ContractError(std::string(__FILE__) + ":" + std::to_string(__LINE__) + \
                                 ": " + (msg));                                           \
  } while (0)

}  // namespace kmr

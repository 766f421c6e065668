#pragma once
// The message of the ContractError that f throws, or "" when it throws none (the sac misuse tests).
#include <string>

#include "exact/error.hpp"

namespace kmr::sac::test {

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const kmr::ContractError& e) {
    return e.what();
  }
  return "";
}

}  // namespace kmr::sac::test

// The failing side of KMR_CHECK (error.hpp): the one place that formats a contract-check message.
#include "exact/error.hpp"

#include <string>

namespace kmr::detail {

void contract_failure(const char* file, int line, const std::string& msg) {
  throw ContractError(std::string(file) + ":" + std::to_string(line) + ": " + msg);
}

void contract_failure(const char* file, int line, const char* msg) {
  contract_failure(file, line, std::string(msg));
}

}  // namespace kmr::detail

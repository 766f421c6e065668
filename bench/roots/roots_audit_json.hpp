#pragma once
// Writes roots_bench's result (claim I2-root-solver-speed) in the `kmr audit --json` format, for
// `kmr audit --include FILE --report DIR`: medians, ratio, and a plot of per-certificate time
// quantiles of kmr and CGAL with the 0.5 x CGAL target. a, b: sorted per-certificate times in ns.
#include <string>
#include <vector>

void write_audit_json(const std::string& path, const std::vector<double>& a, const std::vector<double>& b, int certificates,
                      double paired_ratio, double paired_min, double paired_max);

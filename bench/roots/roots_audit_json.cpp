// roots_bench --audit-json FILE: the run as a kmr audit result (kept out of the CGAL translation
// unit so that changes to audit.hpp do not recompile CGAL).
#include "roots_audit_json.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "audit/audit.hpp"

// The run as an audit result (claim I2-root-solver-speed) for `kmr audit --include FILE --report DIR`.
void write_audit_json(const std::string& path, const std::vector<double>& a, const std::vector<double>& b, int certificates,
                      double paired_ratio, double paired_min, double paired_max) {
  namespace au = kmr::audit;
  au::Result r;
  r.claim = "I2-root-solver-speed";
  r.title = "next_failure_after vs CGAL Algebraic_kernel_d_1 on §2.4 orient3d certificates (bench/roots/roots_bench)";
  double ma = a[a.size() / 2], mb = b[b.size() / 2];
  r.verdict.pass = paired_ratio <= 0.5;  // the stable figure: median of 21 interleaved pairs
  r.replay = "build/bin/roots_bench --audit-json " + path + "  (then kmr audit --include " + path + " --report DIR)";
  r.verdict.summary = std::to_string(certificates) + " cubic certificates, ratio = median over 21 interleaved pairs of passes (thread CPU time); target kmr/CGAL <= 0.5";
  r.verdict.figure("median kmr us", au::fmt(ma / 1e3));
  r.verdict.figure("median CGAL us", au::fmt(mb / 1e3));
  r.verdict.figure("ratio kmr/CGAL (paired median)", au::fmt(paired_ratio));
  r.verdict.figure("paired range", au::fmt(paired_min) + ".." + au::fmt(paired_max));
  kmr::svg::Plot p;
  p.title = "I2-root-solver-speed: time per certificate, kmr vs CGAL (quantiles)";
  p.x = kmr::svg::linear_axis("quantile over certificates", "%");
  p.y = kmr::svg::log_axis("time per certificate", "us");
  kmr::svg::Series sa{"kmr next_failure_after", {}}, sb{"CGAL Algebraic_kernel_d_1", {}}, target{"target: 0.5 x CGAL", {}};
  for (int q : {10, 25, 50, 75, 90}) {
    double ta = a[a.size() * q / 100] / 1e3, tb = b[b.size() * q / 100] / 1e3;
    sa.points.push_back({double(q), ta});
    sb.points.push_back({double(q), tb});
    target.points.push_back({double(q), tb / 2});
  }
  p.series = {sa, sb};
  p.bounds = {target};
  r.verdict.plot(std::move(p));
  std::ofstream out(path);
  kmr::audit::write_json({r}, out);
  if (!out) {
    std::fprintf(stderr, "cannot write --audit-json file '%s'\n", path.c_str());
    std::exit(2);
  }
}


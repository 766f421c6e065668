#!/usr/bin/env python3
"""Writes an lcov tracefile from gcov's JSON output, leaving out exception branches.

Usage: coverage/gcov_to_lcov.py BUILD_DIR SOURCE_PREFIX OUT.info [OUT_WITHOUT_CONTRACT_CHECKS.info]

Why not `lcov --capture --rc geninfo_no_exception_branch=1`: Debian 12's lcov 1.16 defines the JSON
reader of geninfo twice (the "Subroutine ... redefined" warnings), and the second definition, the one
that runs, ignores geninfo_no_exception_branch; its text mode cannot read gcc 12's hashed .gcov names.
So every call that may throw counted as an untaken branch (the edge to its landing pad).

gcov (gcc >= 9) marks those edges `"throw": true`; this script drops them and keeps every other
branch. Counts are merged the way lcov merges tracefiles: per source line, over every translation
unit and every template instantiation, line counts add up and the i-th branch of a line adds to the
i-th branch of that line elsewhere. Only files under SOURCE_PREFIX are kept.

With a fourth argument, a second tracefile is written from the same counters without the branches
of the lines that are exactly a contract check: lines whose code starts with `KMR_CHECK(` (lcov's
`lcov_excl_br_line` idiom for assert macros). A KMR_CHECK throws ContractError when its condition
fails, which only a bug in kmr can make happen; its failing side is, like the exception edges above,
not a decision a test of correct code can take. Only those lines: the continuation lines of a
KMR_CHECK spread over several lines (whose operands may be real decisions) and lines where the check
follows other code (`for (...) KMR_CHECK(...)`) keep their branches. Lines and the first tracefile
are unchanged; coverage/run.sh prints both branch figures.
"""
import json
import os
import re
import subprocess
import sys
from collections import defaultdict


CONTRACT_CHECK = re.compile(r"^\s*KMR_CHECK\(")


def contract_check_lines(path):
    """Line numbers (from 1) of `path` whose code starts with KMR_CHECK( (see the module doc)."""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            return {n for n, text in enumerate(f, start=1) if CONTRACT_CHECK.match(text)}
    except OSError:
        return set()


def write_tracefile(out_path, lines, branches, functions, skip_branch_lines):
    """Writes the lcov tracefile; the branches of the lines in skip_branch_lines(path) are left out."""
    with open(out_path, "w") as out:
        for path in sorted(lines):
            skip = skip_branch_lines(path)
            out.write(f"TN:\nSF:{path}\n")
            fns = functions[path]
            for name, (start, _) in sorted(fns.items(), key=lambda kv: (kv[1][0], kv[0])):
                out.write(f"FN:{start},{name}\n")
            for name, (_, count) in sorted(fns.items(), key=lambda kv: (kv[1][0], kv[0])):
                out.write(f"FNDA:{count},{name}\n")
            out.write(f"FNF:{len(fns)}\nFNH:{sum(1 for _, c in fns.values() if c > 0)}\n")
            brf = brh = 0
            for n in sorted(branches[path]):
                if n in skip:
                    continue
                for k, c in enumerate(branches[path][n]):
                    taken = c if lines[path][n] > 0 else "-"
                    out.write(f"BRDA:{n},0,{k},{taken}\n")
                    brf += 1
                    brh += c > 0
            out.write(f"BRF:{brf}\nBRH:{brh}\n")
            for n in sorted(lines[path]):
                out.write(f"DA:{n},{lines[path][n]}\n")
            lh = sum(1 for c in lines[path].values() if c > 0)
            out.write(f"LF:{len(lines[path])}\nLH:{lh}\nend_of_record\n")


def main():
    build, prefix, out_path = sys.argv[1:4]
    out_without_checks = sys.argv[4] if len(sys.argv) > 4 else None
    gcdas = sorted(os.path.join(d, f) for d, _, fs in os.walk(build) for f in fs if f.endswith(".gcda"))
    if not gcdas:
        sys.exit(f"gcov_to_lcov: no .gcda files under {build} (did the tests run?)")
    lines = defaultdict(lambda: defaultdict(int))       # file -> line -> count
    branches = defaultdict(lambda: defaultdict(list))   # file -> line -> [count of branch i]
    functions = defaultdict(dict)                        # file -> name -> [start line, count]
    for i in range(0, len(gcdas), 64):
        batch = gcdas[i:i + 64]
        res = subprocess.run(["gcov", "--json-format", "--stdout", "--branch-probabilities", *batch], capture_output=True, text=True)
        if res.returncode != 0:
            sys.exit(f"gcov_to_lcov: gcov failed: {res.stderr[:2000]}")
        for doc in res.stdout.splitlines():
            if not doc.strip():
                continue
            data = json.loads(doc)
            cwd = data.get("current_working_directory", "")
            for f in data["files"]:
                path = os.path.normpath(os.path.join(cwd, f["file"]))
                if not path.startswith(prefix):
                    continue
                for fn in f.get("functions", []):
                    entry = functions[path].setdefault(fn["demangled_name"], [fn["start_line"], 0])
                    entry[1] += fn["execution_count"]
                for ln in f["lines"]:
                    n = ln["line_number"]
                    lines[path][n] += ln["count"]
                    counts = [b["count"] for b in ln["branches"] if not b.get("throw", False)]
                    merged = branches[path][n]
                    for k, c in enumerate(counts):
                        if k < len(merged):
                            merged[k] += c
                        else:
                            merged.append(c)
    write_tracefile(out_path, lines, branches, functions, lambda path: set())
    if out_without_checks:
        write_tracefile(out_without_checks, lines, branches, functions, contract_check_lines)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Every doctest case must run as its own ctest test.

doctest_discover_tests registers one ctest test per case and runs it with
`--test-case=NAME` (commas escaped). CMake splits the name at ';', so a case
named with one becomes a fragment that matches no case, runs no assertion
and passes; a backslash would escape the next character of the filter. Two
cases with the same name in one executable would run together under one
entry. This check refuses all three (docs/testing.md).
"""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent / "tests"
case = re.compile(r'TEST_CASE\s*\(\s*"((?:[^"\\]|\\.)*)"')
bad_chars = set(';\\')
problems = []
names_by_module = {}
for path in sorted(root.rglob("*.cpp")):
    text = path.read_text(encoding="utf-8")
    module = path.relative_to(root).parts[0]
    for m in case.finditer(text):
        name = m.group(1)
        line = text.count("\n", 0, m.start()) + 1
        where = f"{path.relative_to(root.parent)}:{line}"
        found = sorted(set(name) & bad_chars)
        if found:
            problems.append(f"{where}: test case name contains {' '.join(repr(c) for c in found)}: \"{name}\"")
        if name != name.strip():
            problems.append(f"{where}: test case name starts or ends with white space")
        seen = names_by_module.setdefault(module, {})
        if name in seen:
            problems.append(f"{where}: test case name also used at {seen[name]}")
        else:
            seen[name] = where
for p in problems:
    print(p)
if problems:
    print(f"{len(problems)} test case names ctest cannot run as written")
    sys.exit(1)
print(f"{sum(len(v) for v in names_by_module.values())} test case names checked")

#!/usr/bin/python3
"""docs/DESIGN.md says every source file is mirrored by a test file, and names the
exceptions with where they are tested. This checks both halves of that sentence:
every src/<area>/<name>.{hpp,cpp} has tests/<area>/<name>_test.cpp (every
python/src/bind_<area>.cpp has python/tests/test_<area>.py) or is an exception, and
every exception is named in docs/DESIGN.md."""

import pathlib
import sys

EXCEPTIONS = {
    # tested through the binary (tests/cli/, the install test)
    "cli/*",
    # tested by tests/ik/ik_solver_test.cpp, which runs both solvers
    "ik/gradient_descent_ik", "ik/damped_least_squares_ik",
    # tested by tests/ik/solver_agreement_test.cpp
    "ik/reach_queries",
    # generated at build time; tested through provenance and crux --version
    "common/build_info",
    # plain types, used by every test that reads inputs or solves IK
    "body/body_data", "ik/ik_result", "common/input_error",
}
PYTHON_EXCEPTIONS = {"conversions", "python_config", "python_errors", "interruption", "module", "bindings"}


def main(root: pathlib.Path) -> int:
    design = (root / "docs" / "DESIGN.md").read_text()
    problems = []
    for name in sorted(EXCEPTIONS | PYTHON_EXCEPTIONS):
        if f"`{name}`" not in design:
            problems.append(f"docs/DESIGN.md does not name the exception `{name}`")
    for source in sorted((root / "src").rglob("*.[ch]pp")):
        relative = source.relative_to(root / "src").with_suffix("")
        area, stem = relative.parent.as_posix(), relative.name
        if f"{area}/{stem}" in EXCEPTIONS or f"{area}/*" in EXCEPTIONS:
            continue
        if not (root / "tests" / area / f"{stem}_test.cpp").exists():
            problems.append(f"src/{area}/{source.name} has no tests/{area}/{stem}_test.cpp")
    for source in sorted((root / "python" / "src").glob("*.[ch]pp")):
        stem = source.stem
        if stem in PYTHON_EXCEPTIONS:
            continue
        area = stem.removeprefix("bind_")
        if not stem.startswith("bind_") or not (root / "python" / "tests" / f"test_{area}.py").exists():
            problems.append(f"python/src/{source.name} has no python/tests/test_{area}.py")
    for problem in problems:
        print(problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1])))

#!/usr/bin/python3
"""docs/DESIGN.md says every source file is mirrored by a test file, and names the
exceptions with where they are tested. This checks both halves of that sentence:
every src/<area>/<name>.{hpp,cpp} has tests/<area>/<name>_test.cpp (every
python/src/bind_<area>.cpp has python/tests/test_<area>.py) or is an exception, and
every exception is named in docs/DESIGN.md.

It also checks DESIGN's folder table, whose order is the direction of dependencies:
every `#include "<area>/..."` of a file in src/<other>/ names its own folder or one
above it in the table, and every folder of src/ has its row; that python/src/ includes
no cli/; that DESIGN's "layers at a glance" lists the table's folders in its order,
the order src/CMakeLists.txt builds the layer libraries in; and that no unit (a header
and its source, src/<area>/<name>.{hpp,cpp}) reaches itself through the units it
includes: no include loop, inside a folder or across folders."""

import pathlib
import re
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
    # tested with the page it summarises, by tests/jobs/report_job_test.cpp
    "reports/written_report",
    # plain types, used by every test that reads inputs or solves IK
    "body/body_data", "ik/ik_result", "common/input_error", "jobs/job_hooks",
}
PYTHON_EXCEPTIONS = {
    "conversions", "python_config", "python_errors", "interruption", "module", "bindings",
    # the environment both bind_climb_env and bind_vector_climb_env step, tested through both
    "climb_episode",
}


def layer_problems(root: pathlib.Path, design: str) -> list[str]:
    order = re.findall(r"^\| `src/([a-z_]+)/` \|", design, flags=re.MULTILINE)
    rank = {area: i for i, area in enumerate(order)}
    problems = [f"docs/DESIGN.md's folder table has two rows for src/{area}/"
                for area in sorted(set(order)) if order.count(area) > 1]
    problems += [f"docs/DESIGN.md's folder table has no row for src/{folder.name}/"
                 for folder in sorted((root / "src").iterdir()) if folder.is_dir() and folder.name not in rank]
    include = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/', flags=re.MULTILINE)
    for source in sorted((root / "src").rglob("*.[ch]pp")):
        # A file in a subfolder belongs to its top folder's layer.
        area = source.relative_to(root / "src").parts[0]
        for used in sorted(set(include.findall(source.read_text()))):
            if used in rank and area in rank and rank[used] > rank[area]:
                problems.append(f"src/{area}/{source.name} includes {used}/, which comes after {area}/ "
                                f"in docs/DESIGN.md's folder table")
    # python/ and src/cli/ both sit on top of the library: each calls the library, neither
    # the other.
    for source in sorted((root / "python" / "src").glob("*.[ch]pp")) if (root / "python" / "src").is_dir() else []:
        for used in sorted(set(include.findall(source.read_text()))):
            if used == "cli":
                problems.append(f"python/src/{source.name} includes cli/: the Python module calls the library, "
                                f"as the command line does, not the command line")
    return problems


def include_loop_problems(root: pathlib.Path) -> list[str]:
    """Units of src/ (area/name, a header and its source together) that include each other
    in a loop, one line per loop found, naming its units in order."""
    include = re.compile(r'^\s*#\s*include\s+"([a-z_]+/[a-z_0-9]+)\.hpp"', flags=re.MULTILINE)
    uses: dict[str, set[str]] = {}
    for source in sorted((root / "src").rglob("*.[ch]pp")):
        unit = source.relative_to(root / "src").with_suffix("").as_posix()
        uses.setdefault(unit, set()).update(used for used in include.findall(source.read_text()) if used != unit)
    problems, done, path = [], set(), []
    on_path: dict[str, int] = {}

    def visit(unit: str) -> None:
        on_path[unit] = len(path)
        path.append(unit)
        for used in sorted(uses.get(unit, ())):
            if used in on_path:
                loop = path[on_path[used]:] + [used]
                problems.append("include loop: " + " -> ".join(loop))
            elif used not in done and used in uses:
                visit(used)
        path.pop()
        del on_path[unit]
        done.add(unit)

    for unit in sorted(uses):
        if unit not in done:
            visit(unit)
    return problems


def glance_problems(root: pathlib.Path, design: str) -> list[str]:
    """DESIGN's "layers at a glance" names the table's src/ folders in the table's order,
    and the library layers in the order of src/CMakeLists.txt's crux_layers."""
    table = re.findall(r"^\| `src/([a-z_]+)/` \|", design, flags=re.MULTILINE)
    glance = re.search(r"## The layers at a glance.*?```\n(.*?)```", design, flags=re.DOTALL)
    if glance is None:
        return ["docs/DESIGN.md has no list of the layers at a glance"]
    listed = re.findall(r"^src/([a-z_]+)/", glance.group(1), flags=re.MULTILINE)
    problems = []
    if listed != table:
        problems.append(f"docs/DESIGN.md's layers at a glance ({', '.join(listed)}) differ from its folder "
                        f"table ({', '.join(table)})")
    cmake = re.search(r"set\(crux_layers ([a-z_\s]+)\)", (root / "src" / "CMakeLists.txt").read_text())
    built = cmake.group(1).split() if cmake else []
    if built != [folder for folder in listed if folder != "cli"]:
        problems.append(f"src/CMakeLists.txt builds the layers {', '.join(built)}, not docs/DESIGN.md's "
                        f"{', '.join(listed)} (cli/ apart)")
    return problems


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
    problems += layer_problems(root, design)
    problems += glance_problems(root, design)
    problems += include_loop_problems(root)
    for problem in problems:
        print(problem)
    return 1 if problems else 0


def self_test() -> int:
    """The layer check on a two-folder tree: an include that points down the table passes, one
    that points up fails, naming the file, as does the Python module's include of cli/."""
    import tempfile
    with tempfile.TemporaryDirectory() as scratch:
        root = pathlib.Path(scratch)
        (root / "src" / "low").mkdir(parents=True)
        (root / "src" / "high").mkdir()
        design = "| folder | what |\n|---|---|\n| `src/low/` | x |\n| `src/high/` | y |\n"
        (root / "src" / "high" / "user.cpp").write_text('#include "low/base.hpp"\n')
        (root / "src" / "low" / "base.hpp").write_text("#pragma once\n")
        if layer_problems(root, design):
            print("self-test: an include of a folder above was refused")
            return 1
        (root / "src" / "low" / "base.hpp").write_text('#pragma once\n#include "high/user.hpp"\n')
        if layer_problems(root, design) != ["src/low/base.hpp includes high/, which comes after low/ in "
                                            "docs/DESIGN.md's folder table"]:
            print("self-test: an include of a folder below was not refused")
            return 1
        (root / "python" / "src").mkdir(parents=True)
        (root / "python" / "src" / "bind_x.cpp").write_text('#include "low/base.hpp"\n#include "cli/flags.hpp"\n')
        if not any("python/src/bind_x.cpp includes cli/" in p for p in layer_problems(root, design)):
            print("self-test: the Python module's include of cli/ was not refused")
            return 1
        (root / "python" / "src" / "bind_x.cpp").write_text('#include "low/base.hpp"\n')
        (root / "src" / "unlisted").mkdir()
        if not any("no row for src/unlisted/" in p for p in layer_problems(root, design)):
            print("self-test: a folder without a row was not named")
            return 1
        # A loop within one folder: a's source includes b, whose header includes a.
        (root / "src" / "low" / "base.hpp").write_text("#pragma once\n")
        (root / "src" / "low" / "a.hpp").write_text("#pragma once\n")
        (root / "src" / "low" / "a.cpp").write_text('#include "low/a.hpp"\n#include "low/b.hpp"\n')
        (root / "src" / "low" / "b.hpp").write_text('#pragma once\n#include "low/base.hpp"\n')
        if include_loop_problems(root):
            print("self-test: units that include each other one way were called a loop")
            return 1
        (root / "src" / "low" / "b.hpp").write_text('#pragma once\n#include "low/a.hpp"\n')
        if include_loop_problems(root) != ["include loop: low/a -> low/b -> low/a"]:
            print("self-test: a loop between a source and a header was not named: "
                  + repr(include_loop_problems(root)))
            return 1
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: check_mirrors.py REPOSITORY | --self-test")
    if sys.argv[1] == "--self-test":
        sys.exit(self_test())
    sys.exit(main(pathlib.Path(sys.argv[1])))

#!/usr/bin/python3
"""docs/MODEL.md numbers the choices crux makes where the paper is silent ("choice C7"),
and code and docs cite them by number. This checks that every cited number is defined
there (once, with its anchor), and that nothing cites the numbered items of the
specification file crux was first written against, which lives outside the repository
and which its readers cannot open."""

import pathlib
import re
import sys

# Where citations may be: the sources, tests, docs and everything else that is written
# by hand. Build trees and installed npm packages are not.
SKIPPED_FOLDERS = {".git", "build", "node_modules"}
TEXT_SUFFIXES = {".cpp", ".hpp", ".py", ".md", ".sh", ".cmake", ".txt", ".toml", ".json", ".urdf", ".js", ".css",
                 ".html", ".in"}

DEFINITION = re.compile(r'<a id="choice-c(\d+)"></a>\*\*C(\d+)\.')
# "choice C7", "choices C2 and C13", "choices C3, C4 or C8", across line breaks and
# comment markers.
CITATION = re.compile(r"\bchoices?(?:\s|//|#)+(C\d+(?:(?:\s|//|#)*(?:,|and|or)(?:\s|//|#)*C\d+)*)", re.IGNORECASE)
# Inside the list itself, choices refer to each other as "(C5)"; H(C4) is the paper's
# root target of a 4-configuration, not a choice.
BARE_NUMBER = re.compile(r"(?<!H\()\bC(\d+)\b")
# (Character classes keep this file itself out of a plain grep for those citations.)
OUTSIDE = re.compile(r"\bspe[c](?:\s|//|#|\*)*items?\b|shared[/]spec\b", re.IGNORECASE)
SECTION = "## Choices where the paper is silent"


def numbers(text: str) -> list[int]:
    return [int(n) for n in re.findall(r"C(\d+)", text)]


def main(root: pathlib.Path) -> int:
    model = (root / "docs" / "MODEL.md").read_text()
    problems = []
    defined = {}
    for anchor, label in DEFINITION.findall(model):
        if anchor != label:
            problems.append(f"docs/MODEL.md: choice C{label} has the anchor choice-c{anchor}")
        if int(label) in defined:
            problems.append(f"docs/MODEL.md: choice C{label} is defined twice")
        defined[int(label)] = True
    if not defined:
        problems.append("docs/MODEL.md defines no choice")
    if SECTION in model:
        section = model[model.index(SECTION):]
        for n in sorted({int(n) for n in BARE_NUMBER.findall(section)} - set(defined)):
            problems.append(f"docs/MODEL.md: the choices refer to C{n}, which is not defined")
    else:
        problems.append(f'docs/MODEL.md has no section "{SECTION[3:]}"')

    this_file = pathlib.Path(__file__).resolve()
    for path in sorted(root.rglob("*")):
        relative = path.relative_to(root)
        if any(part in SKIPPED_FOLDERS for part in relative.parts) or not path.is_file():
            continue
        if path.suffix not in TEXT_SUFFIXES or path.resolve() == this_file:
            continue
        text = path.read_text(errors="replace")
        for match in CITATION.finditer(text):
            line = text.count("\n", 0, match.start()) + 1
            for n in numbers(match.group(1)):
                if n not in defined:
                    problems.append(f"{relative}:{line}: cites choice C{n}, which docs/MODEL.md does not define")
        for match in OUTSIDE.finditer(text):
            line = text.count("\n", 0, match.start()) + 1
            cited = " ".join(match.group(0).split())
            problems.append(f"{relative}:{line}: cites '{cited}', a document outside the repository; "
                            "cite docs/MODEL.md's choices instead")
    for problem in problems:
        print(problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1])))

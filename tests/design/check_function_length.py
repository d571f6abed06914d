#!/usr/bin/python3
"""The project's rule that no function is longer than 80 lines, counted from the first
line of its declaration (a `template <...>` line included) to its closing brace. This
checks every .cpp and .hpp under src/ and python/src/, and prints one line per function
that breaks it.

It is a heuristic, not a parser: comments, literals and preprocessor lines are blanked
(keeping line numbers), then every `{` at namespace or class scope is classified by the
text before it since the last `;`, `{`, `}` or access label. A namespace or `extern`
block is entered; a class, struct or union body is entered too, for its member functions;
an enum or an initializer (`= {`, `name{...}`, `f({...})`) is skipped whole; any other
block with a parameter list `(...)` before it is a function body, measured to its
matching `}` (so its lambdas count as part of it). Braces of a constructor's member
initializers (`a_{a},`) are followed by `,` or `{` and are read as part of the
declaration."""

import pathlib
import re
import sys

LIMIT = 80
IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def blank_non_code(text: str) -> str:
    """The text with comments, string and character literals and preprocessor lines
    replaced by spaces, newlines kept, so that braces inside them do not count."""
    out = list(text)
    i, n = 0, len(text)
    line_start = True

    def blank(start: int, end: int) -> None:
        for k in range(start, end):
            if out[k] != "\n":
                out[k] = " "

    while i < n:
        c = text[i]
        if c == "\n":
            line_start = True
            i += 1
            continue
        if line_start and c == "#":
            # A directive runs to the end of its line, and on past a trailing backslash.
            end = i
            while end < n and text[end] != "\n":
                end += 1
                if end < n and text[end] == "\n" and text[end - 1] == "\\":
                    end += 1
            blank(i, end)
            i = end
            continue
        if not c.isspace():
            line_start = False
        if text.startswith("//", i):
            end = text.find("\n", i)
            end = n if end < 0 else end
            blank(i, end)
            i = end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            blank(i, end)
            i = end
        elif c == '"' and i > 0 and text[i - 1] == "R" and not (i > 1 and (text[i - 2].isalnum() or text[i - 2] == "_")
                                                                  and text[i - 2] not in "u8LU"):
            # A raw string: R"delim( ... )delim".
            open_paren = text.find("(", i)
            delimiter = text[i + 1:open_paren]
            end = text.find(")" + delimiter + '"', open_paren)
            end = n if end < 0 else end + len(delimiter) + 2
            blank(i, end)
            i = end
        elif c in "\"'":
            if c == "'" and is_digit_separator(text, i):
                i += 1
                continue
            end = i + 1
            while end < n and text[end] != c and text[end] != "\n":
                end += 2 if text[end] == "\\" else 1
            blank(i, end + 1)
            i = end + 1
        else:
            i += 1
    return "".join(out)


def is_digit_separator(text: str, i: int) -> bool:
    """Whether the quote at i is inside a number (1'000'000), not a character literal."""
    start = i
    while start > 0 and (text[start - 1].isalnum() or text[start - 1] in "_.'"):
        start -= 1
    return start < i and text[start].isdigit()


def matching_brace(code: str, open_index: int) -> int:
    depth = 0
    for k in range(open_index, len(code)):
        if code[k] == "{":
            depth += 1
        elif code[k] == "}":
            depth -= 1
            if depth == 0:
                return k
    return len(code) - 1


def top_level(head: str) -> str:
    """The head with what is inside (...) and <...> blanked, so that keywords of template
    parameters or of a default argument are not taken for the declaration's own."""
    out, parens, angles = [], 0, 0
    for k, c in enumerate(head):
        before = head[:k].rstrip()
        if c == "(":
            out.append("(" if parens == 0 and angles == 0 else " ")
            parens += 1
            continue
        if c == ")":
            parens = max(parens - 1, 0)
            out.append(")" if parens == 0 and angles == 0 else " ")
            continue
        if c == "<" and parens == 0 and not before.endswith("operator") and not before.endswith("<"):
            angles += 1
        elif c == ">" and parens == 0 and angles > 0 and not before.endswith("-"):
            angles -= 1
            out.append(" ")
            continue
        out.append(c if parens == 0 and angles == 0 else " ")
    return "".join(out)


def parameter_list(head: str) -> int:
    """Where the function's parameter list opens in head, or -1: the first `(` outside <...>
    that follows a name (or `operator X`) which is not a keyword such as decltype."""
    shape = top_level(head)
    for k, c in enumerate(head):
        if c != "(" or shape[k] != "(":
            continue
        before = head[:k].rstrip()
        if re.search(r"operator\s*$", before):
            continue  # operator() names itself with the first pair
        word = re.search(r"(operator\s*\S+|~?[A-Za-z_][A-Za-z0-9_]*)$", before)
        if word and word.group(1) not in {"decltype", "noexcept", "alignas", "requires", "__attribute__", "sizeof"}:
            return k
    return -1


def function_name(head: str, paren: int) -> str:
    before = head[:paren].rstrip()
    match = re.search(r"((?:[A-Za-z_][A-Za-z0-9_]*(?:<[^<>]*>)?\s*::\s*)*(?:operator\s*\S+|~?[A-Za-z_][A-Za-z0-9_]*))$",
                      before)
    return re.sub(r"\s+", "", match.group(1)) if match else "?"


def classify(head: str) -> str:
    """'scope' (entered, its contents at the same level), 'function' or 'other' (skipped)."""
    stripped = head.strip()
    shape = top_level(stripped)
    words = set(IDENTIFIER.findall(shape))
    if words & {"namespace", "extern"} and "(" not in shape:
        return "scope"
    if words & {"struct", "class", "union"} and "(" not in shape:
        return "scope"
    if "enum" in words:
        return "other"
    if not stripped or stripped[-1] in "=(,[{<+-*/|&?:" or re.search(r"=\s*$|\breturn$", stripped):
        return "other"
    if re.search(r"(?<![=!<>])=(?!=)", shape.replace("operator=", "").replace("operator==", "")):
        return "other"  # a variable's initializer, a lambda's included
    return "function" if parameter_list(stripped) >= 0 else "other"


def long_functions(text: str, limit: int = LIMIT) -> list[tuple[int, str, int]]:
    """(line, name, length) of every function in text longer than limit lines."""
    code = blank_non_code(text)
    found = []
    head_start = 0
    i = 0
    while i < len(code):
        c = code[i]
        if c in ";}":
            head_start = i + 1
        elif c == ":" and re.search(r"\b(public|private|protected)\s*$", code[head_start:i]):
            head_start = i + 1
        elif c == "{":
            head = code[head_start:i]
            kind = classify(head)
            if kind == "scope":
                head_start = i + 1
            else:
                close = matching_brace(code, i)
                after = code[close + 1:].lstrip()[:1]
                if kind == "function" and after not in (",", "{"):
                    first = head_start + len(head) - len(head.lstrip())
                    line = code.count("\n", 0, first) + 1
                    length = code.count("\n", first, close) + 1
                    if length > limit:
                        stripped = head.strip()
                        found.append((line, function_name(stripped, parameter_list(stripped)), length))
                    head_start = close + 1
                elif kind != "function" or after not in (",", "{"):
                    head_start = close + 1
                # else: a member initializer's braces; the declaration goes on.
                i = close
        i += 1
    return found


def sources(root: pathlib.Path) -> list[pathlib.Path]:
    folders = [root / "src", root / "python" / "src"]
    return sorted(p for folder in folders if folder.is_dir() for p in folder.rglob("*") if p.suffix in {".cpp", ".hpp"})


def main(root: pathlib.Path) -> int:
    problems = []
    for source in sources(root):
        for line, name, length in long_functions(source.read_text()):
            problems.append(f"{source.relative_to(root)}:{line}: function {name} is {length} lines (limit {LIMIT})")
    for problem in problems:
        print(problem)
    return 1 if problems else 0


def function_of(lines: int, name: str = "f") -> str:
    """A function of exactly `lines` lines, signature to closing brace, with braces,
    strings and comments inside that must not end it early."""
    body = ["  int total = 0;", '  const char* text = "}}";', "  // }", "  const char brace = '}';",
            "  auto add = [&](int x) {", "    total += x;", "  };"]
    body += [f"  add({k});" for k in range(lines - 2 - len(body) - 1)]
    return "\n".join([f"int {name}(int a) {{", *body, "  return total + a + brace + text[0];", "}"]) + "\n"


def self_test() -> int:
    """The check on small sources: a function one line over the limit is named with its
    length, one at the limit passes, and long blocks that are not functions (a namespace,
    a struct of short members, an initializer table, an enum) are not counted."""
    cases = [
        ("an 81-line function", function_of(81), [(1, "f", 81)]),
        ("an 80-line function", function_of(80), []),
        ("an 81-line function after a template line and in a namespace",
         "namespace a {\nnamespace {\ntemplate <class T>\n" + function_of(80, "g") + "}\n}\n", [(3, "g", 81)]),
        ("a long namespace of short functions",
         "namespace n {\n" + "".join(function_of(10, f"f{k}") for k in range(20)) + "}  // namespace n\n", []),
        ("a long struct with short members and one long member function",
         "struct S {\n public:\n  int x_{0};\n  std::function<void()> cb_{};\n"
         + "".join(f"  int m{k}() const {{ return {k}; }}\n" for k in range(100))
         + "  S(int a) : x_{a}, cb_{} {}\n" + function_of(81, "  long_member") + "};\n",
         [(106, "long_member", 81)]),
        ("a constructor whose member initializers have braces",
         "S::S(int a)\n    : x_{a},\n      y_{\n          a} {\n" + "  x_ += 1;\n" * 80 + "}\n", [(1, "S::S", 85)]),
        ("an initializer table",
         "const std::array<Row, 100> kRows = {{\n" + "    {f(1), 2},\n" * 100 + "}};\n"
         + "const std::vector<int> kMore = make({\n" + "    1,\n" * 100 + "});\n"
         + "const Table kTable{\n" + "    Row(1, 2),\n" * 100 + "};\n", []),
        ("an enum", "enum class Kind : int {\n" + "  k,\n" * 100 + "};\n", []),
        ("a long operator()", "struct F {\n  int operator()(int a) const {\n" + "    a += 1;\n" * 80 + "    return a;\n  }\n};\n",
         [(2, "operator()", 83)]),
    ]
    failed = 0
    for what, source, expected in cases:
        got = long_functions(source)
        if got != expected:
            print(f"self-test: {what}: expected {expected}, found {got}")
            failed = 1
    return failed


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: check_function_length.py REPOSITORY | --self-test")
    if sys.argv[1] == "--self-test":
        sys.exit(self_test())
    sys.exit(main(pathlib.Path(sys.argv[1])))

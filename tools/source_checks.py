#!/usr/bin/env python3
"""Source checks run by `./signweave test` (suite "source checks"): size, format and layers.

    tools/source_checks.py [sizes] [format] [layers]      (no argument: all three)
    tools/source_checks.py --write-size-allowlist         (rewrite the size allowlist from today)

sizes   every file in src/ over 800 lines and every function in src/ over 150 lines (the limits
        of docs/STYLE.md and issue 26). A ratchet: tools/source_checks/size_allowlist.txt holds
        today's offenders with their sizes; a check fails when an offender is not listed or has
        grown past its listed size, and passes while a listed one shrinks (a note says when an
        entry can go).
format  `clang-format --dry-run --Werror` on src/, server/, cli/ and tests/native; the files in
        tools/source_checks/format_allowlist.txt are skipped until they are formatted (a note
        says when a listed file is already formatted and can leave the list).
layers  an #include "dir/..." in src/ must point down or sideways in the layer order LAYERS;
        the known upward includes are in tools/source_checks/layer_allowlist.txt, which must
        only shrink: a listed include that no longer exists is reported so the entry can go.

Each checked item counts once; the last line is "N passed, N failed". Exit status 1 on failure.
Functions are found by a brace scanner (comments, strings and the #else branches of
preprocessor conditionals blanked), not a compiler: a function is a brace block at namespace or
class scope whose header ends in a parameter list; lambdas and local classes count toward the
function that holds them. Its length runs from the first line of its header to its closing brace.
"""
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LISTS = os.path.join(ROOT, "tools", "source_checks")
SOURCE_EXTS = (".h", ".cpp", ".inc", ".cc", ".hpp")
FILE_LIMIT = 800
FUNCTION_LIMIT = 150
FORMAT_DIRS = ("src", "server", "cli", os.path.join("tests", "native"))

# The layer order, lowest first, as the includes stand today: a layer may include its own files
# and those of any layer before it. Outside src/ (server/, cli/, tests/) nothing may be included.
LAYERS = ["text", "math", "skeleton", "notation", "avatar", "skinning", "face", "synthesis", "wasm"]


class Tally:
    def __init__(self):
        self.passed = 0
        self.failed = 0

    def ok(self):
        self.passed += 1

    def fail(self, message):
        self.failed += 1
        print("FAIL " + message)


def source_files(top):
    out = []
    for base, dirs, files in os.walk(os.path.join(ROOT, top)):
        dirs.sort()
        for name in sorted(files):
            if name.endswith(SOURCE_EXTS):
                out.append(os.path.relpath(os.path.join(base, name), ROOT))
    return out


def read_list(name):
    """Non-empty, non-comment lines of an allowlist, split on whitespace."""
    rows = []
    with open(os.path.join(LISTS, name), encoding="utf-8") as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                rows.append(line.split())
    return rows


# ---- blanking: comments, literals and inactive preprocessor branches become spaces ----------

def blank_code(text):
    """Comments, string and character literals, and preprocessor lines become spaces (newlines
    kept, so line numbers hold); of an #if/#elif/#else chain only the first branch stays."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c == "/" and text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif c == "/" and text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^()\\ ]{0,16})\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = text.find(")" + m.group(1) + '"', i + m.end())
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append('"' + re.sub(r"[^\n]", " ", text[i + 1:j - 1]) + '"')
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():
                out.append(c)  # a digit separator (1'000'000)
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(c + " " * (j - i - 2) + c if j - i >= 2 else text[i:j])
            i = j
        else:
            out.append(c)
            i += 1
    return blank_preprocessor("".join(out))


def blank_preprocessor(text):
    lines = text.split("\n")
    skipping = []  # per open #if: True while inside a branch after the first
    continued = False
    for k, line in enumerate(lines):
        stripped = line.lstrip()
        directive = continued or stripped.startswith("#")
        if directive:
            if not continued:
                word = re.match(r"#\s*(\w*)", stripped).group(1)
                if word in ("if", "ifdef", "ifndef"):
                    skipping.append(False)
                elif word in ("elif", "else") and skipping:
                    skipping[-1] = True
                elif word == "endif" and skipping:
                    skipping.pop()
            continued = line.rstrip().endswith("\\")
            lines[k] = ""
        elif any(skipping):
            lines[k] = ""
    return "\n".join(lines)


# ---- functions ---------------------------------------------------------------------------

FUNC_TAIL = re.compile(
    r"\)\s*(?:(?:const|noexcept(?:\s*\([^()]*\))?|override|final|mutable|&&|&|volatile)\s*)*"
    r"(?:->\s*[\w:<>,\s\*&]+)?\s*$")
CTOR_INIT = re.compile(r"\)\s*(?:noexcept\s*)?:\s*[\w:]")
NAME_BEFORE_PAREN = re.compile(r"((?:[\w~]+\s*::\s*)*(?:operator\s*[^\s(]+|operator\s*\(\s*\)|[\w~]+))\s*$")


def function_name(header):
    depth_angle = 0
    for k, ch in enumerate(header):
        if ch == "<":
            depth_angle += 1
        elif ch == ">":
            depth_angle = max(0, depth_angle - 1)
        elif ch == "(" and depth_angle == 0:
            m = NAME_BEFORE_PAREN.search(header[:k])
            if m and m.group(1) not in ("if", "for", "while", "switch", "return", "decltype"):
                return re.sub(r"\s+", "", m.group(1))
    return None


def classify(header):
    """What a '{' at namespace or class scope opens, from the text since the last ; { or }."""
    h = re.sub(r"\b(?:public|private|protected)\s*:(?!:)", " ", header).strip()
    if re.match(r"(?:inline\s+)?namespace\b", h) or re.match(r'extern\s+"', h):
        return "namespace"
    if re.match(r"enum\b", h) or re.search(r"=\s*$", h) or re.search(r"\benum\s+(class|struct)\b", h):
        return "other"
    if FUNC_TAIL.search(h) or (CTOR_INIT.search(h) and h.rstrip().endswith(")")):
        return "function"
    if CTOR_INIT.search(h):
        # a brace initialiser in a constructor's member-initialiser list: not the body yet
        return "init"
    if re.match(r"(?:template\s*<.*>\s*)?(?:class|struct|union)\b", h, re.S):
        return "class"
    return "other"


def functions(path):
    """(name, first_line, length_lines) for each function defined in a file."""
    with open(os.path.join(ROOT, path), encoding="utf-8", errors="replace") as f:
        text = blank_code(f.read())
    found = []
    stack = []  # kinds of the open braces at namespace/class scope
    header_start = 0
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c in ";}":
            if c == "}" and stack:
                kind = stack.pop()
                if kind == "init":
                    i += 1
                    continue  # the constructor's header goes on
            header_start = i + 1
        elif c == "{":
            header = text[header_start:i]
            kind = classify(header)
            if kind in ("function", "other"):
                end = matching_brace(text, i)
                if kind == "function":
                    name = function_name(header) or "?"
                    lead = len(header) - len(header.lstrip())
                    first = text.count("\n", 0, header_start + lead) + 1
                    last = text.count("\n", 0, end) + 1
                    found.append((name, first, last - first + 1))
                i = end + 1
                header_start = i
                continue
            stack.append(kind)
            if kind != "init":
                header_start = i + 1
        i += 1
    return found


def matching_brace(text, i):
    depth = 0
    for j in range(i, len(text)):
        if text[j] == "{":
            depth += 1
        elif text[j] == "}":
            depth -= 1
            if depth == 0:
                return j
    return len(text) - 1


# ---- the checks --------------------------------------------------------------------------

def size_offenders():
    """{key: size} for today's files over FILE_LIMIT and functions over FUNCTION_LIMIT in src/."""
    offenders = {}
    for path in source_files("src"):
        with open(os.path.join(ROOT, path), encoding="utf-8", errors="replace") as f:
            lines = sum(1 for _ in f)
        if lines > FILE_LIMIT:
            offenders["file " + path] = lines
        seen = {}
        for name, _first, length in functions(path):
            if length > FUNCTION_LIMIT:
                seen[name] = seen.get(name, 0) + 1
                key = "function %s:%s" % (path, name)
                if seen[name] > 1:
                    key += "#%d" % seen[name]
                offenders[key] = length
    return offenders


def check_sizes(t):
    allowed = {"%s %s" % (kind, key): int(size) for kind, key, size in read_list("size_allowlist.txt")}
    offenders = size_offenders()
    for key, size in sorted(offenders.items()):
        limit = allowed.get(key)
        if limit is None:
            t.fail("%s has %d lines (limit %d); split it rather than list it" %
                   (key, size, FILE_LIMIT if key.startswith("file") else FUNCTION_LIMIT))
        elif size > limit:
            t.fail("%s grew to %d lines (allowlist: %d); the list may only shrink" % (key, size, limit))
        else:
            if size < limit:
                print("note %s is down to %d lines (listed %d): lower its entry" % (key, size, limit))
            t.ok()
    for key in sorted(set(allowed) - set(offenders)):
        print("note %s is within the limit now: remove it from size_allowlist.txt" % key)
    checked = len(source_files("src"))
    t.passed += checked - len({k.split()[1].split(":")[0] for k in offenders})
    print("sizes: %d files in src/, %d offenders (%d listed)" % (checked, len(offenders), len(allowed)))


def check_format(t):
    tool = shutil.which("clang-format")
    if not tool:
        t.fail("clang-format is not installed (apt-get install clang-format)")
        return
    skip = {row[0] for row in read_list("format_allowlist.txt")}
    paths = [p for top in FORMAT_DIRS for p in source_files(top)]
    # One run over every file (a process per file took minutes on a loaded machine); each
    # violation is reported as "FILE:LINE:COL: error: ...".
    r = subprocess.run([tool, "--dry-run", "--Werror"] + paths, cwd=ROOT,
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    unformatted = {line.split(":", 1)[0] for line in r.stderr.splitlines() if ": error:" in line}
    if r.returncode != 0 and not unformatted:
        t.fail("clang-format failed: " + r.stderr.strip()[:300])
    skipped = 0
    for path in paths:
        if path in skip:
            skipped += 1
            if path not in unformatted:
                print("note %s is formatted now: remove it from format_allowlist.txt" % path)
        elif path in unformatted:
            t.fail("%s is not clang-formatted (run: clang-format -i %s)" % (path, path))
        else:
            t.ok()
    print("format: %d files skipped by format_allowlist.txt" % skipped)


INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def upward_includes():
    """[(file, included)] for each include in src/ that points up the layer order or out of src/."""
    rank = {name: k for k, name in enumerate(LAYERS)}
    bad = []
    for path in source_files("src"):
        layer = path.split(os.sep)[1]
        with open(os.path.join(ROOT, path), encoding="utf-8", errors="replace") as f:
            includes = INCLUDE.findall(f.read())
        for inc in includes:
            target = inc.split("/")[0] if "/" in inc else layer
            if target == layer:
                continue
            if layer not in rank or target not in rank or rank[target] > rank[layer]:
                bad.append((path, inc))
    return bad


def check_layers(t):
    allowed = {(row[0], row[1]) for row in read_list("layer_allowlist.txt")}
    bad = upward_includes()
    for path, inc in bad:
        if (path, inc) in allowed:
            t.ok()
        else:
            t.fail('%s includes "%s", which points up the layer order %s' %
                   (path, inc, " < ".join(LAYERS)))
    for path, inc in sorted(allowed - set(bad)):
        print('note %s no longer includes "%s" upward: remove it from layer_allowlist.txt' % (path, inc))
    files = source_files("src")
    t.passed += len(files) - len({p for p, _ in bad})
    print("layers: %d files in src/, %d upward includes (%d listed)" % (len(files), len(bad), len(allowed)))


def write_size_allowlist():
    path = os.path.join(LISTS, "size_allowlist.txt")
    with open(path, encoding="utf-8") as f:
        head = [line for line in f if line.startswith("#")]
    with open(path, "w", encoding="utf-8") as f:
        f.writelines(head)
        for key, size in sorted(size_offenders().items()):
            f.write("%s %d\n" % (key, size))


def main(argv):
    if argv == ["--write-size-allowlist"]:
        write_size_allowlist()
        return 0
    checks = {"sizes": check_sizes, "format": check_format, "layers": check_layers}
    names = argv or list(checks)
    unknown = [a for a in names if a not in checks]
    if unknown:
        print(__doc__)
        return 2
    t = Tally()
    for name in names:
        checks[name](t)
    print("%d passed, %d failed" % (t.passed, t.failed))
    return 1 if t.failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

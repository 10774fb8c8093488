#!/usr/bin/env python3
"""check-architecture.py [SOURCE_DIR]: docs/ARCHITECTURE.md's module table against the code.

Each folder's dependencies are derived from the #include "..." lines of the files in it (src/NAME
and its subfolders, menus, menus/term directly): an include "orbit/sgp4.h" is a dependency on orbit, "menus/term/x.h"
on term. The table's "depends on" cell must name exactly those folders (by their last path part;
"nothing" or an empty cell for none). Outside libraries in the cell (libcurl, ncurses, ...) are
not checked here: CMake's target_link_libraries says what links. Every folder must have a row.
The folders' dependencies must also form no cycle (src/app over src/cli over src/live, ...): a
cycle is named with the include that closes it. Exits 1 naming each folder and each dependency on
which the two disagree; run by CTest (`architecture_table`).

And the one door (issue 55): only the model's owner writes the station's store::Model. Outside
src/store (the owner, the state reader and the pure transforms of a model value), no file may hold
a writable Model: no `Model&` that is not const, except the parameter of a change handed to the
owner (`owner.edit(..., [&](store::Model& m) { ... })`, a lambda's `](store::Model& m)`, or the
type of such a change, `function<void(store::Model&)>`). Each
breach is named with its line. `--writers` lists the files that hold a writable Model and exits 0
(for a before/after count); `--table` prints each folder's derived dependencies.

It also holds the one door for JSON from outside (issue 56): every parse goes through
json_limits::parse_bounded (src/util/json_limits.h: the nesting bound, then the parse), so a
`json::parse(` (nlohmann::json, ordered_json, any spelling) or `sax_parse(` anywhere else in src/,
menus/ or bench/ fails the check, naming the file and line, unless the line is one of JSON_PARSE_ALLOWED below:
text trakbox wrote itself.
"""
import os
import re
import sys

ARGS = [a for a in sys.argv[1:] if not a.startswith("--")]
ROOT = os.path.abspath(ARGS[0] if ARGS else os.path.join(os.path.dirname(__file__), ".."))
DOC = os.path.join(ROOT, "docs", "ARCHITECTURE.md")
EXTERNAL = {"nlohmann-json", "pugixml", "libcurl", "libgps", "ncurses", "boost.asio", "spdlog", "hamlib", "libsqlite3", "nothing", "—", "-", ""}


def modules():
    """{'src/orbit': 'orbit', ..., 'menus': 'menus', 'menus/term': 'term'}"""
    out = {}
    for name in sorted(os.listdir(os.path.join(ROOT, "src"))):
        if os.path.isdir(os.path.join(ROOT, "src", name)):
            out[f"src/{name}"] = name
    out["menus"] = "menus"
    out["menus/term"] = "term"
    return out


def include_target(path, mods):
    """The module an include path names, if any: the longest folder it starts with."""
    candidates = []
    for folder, short in mods.items():
        rel = folder[len("src/"):] if folder.startswith("src/") else folder
        if path.startswith(rel + "/"):
            candidates.append((len(rel), short))
    return max(candidates)[1] if candidates else None


def derived(mods):
    deps = {}
    for folder, short in mods.items():
        d = os.path.join(ROOT, folder)
        found = {}
        files = sorted(os.listdir(d))
        if folder.startswith("src/"):   # a module's subfolders are part of it (src/radio/icom/ ...)
            files += sorted(os.path.join(sub, f) for sub in os.listdir(d) if os.path.isdir(os.path.join(d, sub))
                            for f in os.listdir(os.path.join(d, sub)))
        for f in files:
            if not f.endswith((".cpp", ".h")):
                continue
            with open(os.path.join(d, f), encoding="utf-8") as fh:
                for line in fh:
                    m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
                    if not m:
                        continue
                    target = include_target(m.group(1), mods)
                    if target and target != short:
                        found.setdefault(target, f"{folder}/{f}: #include \"{m.group(1)}\"")
        deps[short] = (folder, found)
    return deps


def documented(mods):
    rows = {}
    with open(DOC, encoding="utf-8") as fh:
        for line in fh:
            m = re.match(r"\|\s*`([^`]+)`\s*\|.*\|\s*([^|]*)\|\s*$", line)
            if not m:
                continue
            folder = m.group(1).rstrip("/")
            if folder not in mods:
                continue
            names = {n.strip().lower() for n in m.group(2).split(",")}
            rows[mods[folder]] = {n for n in names if n not in EXTERNAL}
    return rows


def cycles(code):
    """Each loop of folders that include one another, as 'a -> b -> a' with the includes."""
    graph = {short: sorted(found) for short, (_, found) in code.items()}
    out, state = [], {}

    def visit(node, path):
        state[node] = "open"
        for nxt in graph.get(node, []):
            if state.get(nxt) == "open":
                loop = path[path.index(nxt):] + [nxt]
                out.append(" -> ".join(loop) + " (" + "; ".join(code[a][1][b] for a, b in zip(loop, loop[1:])) + ")")
            elif nxt not in state:
                visit(nxt, path + [nxt])
        state[node] = "done"

    for node in sorted(graph):
        if node not in state:
            visit(node, [node])
    return out


WRITABLE = re.compile(r"(?<![\w:])(?:store::)?Model\s*&(?!&)")
LAMBDA_PARAM = re.compile(r"(?:\]\s*|void)\(\s*(?:store::)?Model\s*&")


def model_writers():
    """[(file, line number, text)] of writable Model references outside src/store."""
    out = []
    for top in ("src", "menus"):
        for dirpath, _, files in os.walk(os.path.join(ROOT, top)):
            rel_dir = os.path.relpath(dirpath, ROOT)
            if rel_dir == "src/store" or rel_dir.startswith("src/store/"):
                continue
            for f in sorted(files):
                if not f.endswith((".cpp", ".h")):
                    continue
                with open(os.path.join(dirpath, f), encoding="utf-8") as fh:
                    for n, line in enumerate(fh, 1):
                        code = line.split("//")[0]
                        for m in WRITABLE.finditer(code):
                            before = code[:m.start()]
                            if re.search(r"\bconst\s+$", before):
                                continue
                            if LAMBDA_PARAM.search(code[max(0, m.start() - 12):m.end()]):
                                continue
                            out.append((os.path.join(rel_dir, f), n, line.strip()))
    return out


# (file, a piece of the line): parses of text trakbox wrote itself, each with why it may skip the door.
JSON_PARSE_ALLOWED = [
    ("src/util/json_limits.h", "return Json::parse(text.begin(), text.end());"),  # the door itself
    # the station's own events, kept as the text it wrote for the live feed's replay
    ("src/web/server.cpp", "events.push_back(nlohmann::json::parse(e, nullptr, false));"),
    # the state document's data written by dump() a line above, read back to clean its strings
    ("src/store/state_file.cpp", "nlohmann::json::parse(data.dump(-1, ' ', false, kReplace));"),
]
JSON_PARSE = re.compile(r"\w*json\s*::\s*(?:parse|sax_parse)\s*\(|\bsax_parse\s*\(", re.IGNORECASE)


def json_parse_outside_door():
    """Each `json::parse(` outside json_limits::parse_bounded and the allowed lines."""
    out, used = [], set()
    for top in ("src", "menus", "bench"):
        for dirpath, _, files in os.walk(os.path.join(ROOT, top)):
            for f in sorted(files):
                if not f.endswith((".cpp", ".h")):
                    continue
                path = os.path.join(dirpath, f)
                rel = os.path.relpath(path, ROOT)
                with open(path, encoding="utf-8") as fh:
                    for n, line in enumerate(fh, 1):
                        if not JSON_PARSE.search(line) or line.lstrip().startswith("//"):
                            continue
                        allowed = [a for a in JSON_PARSE_ALLOWED if a[0] == rel and a[1] in line]
                        if allowed:
                            used.add(allowed[0])
                            continue
                        out.append(f"{rel}:{n}: JSON parsed outside json_limits::parse_bounded (src/util/json_limits.h: "
                                   f"the nesting bound first): {line.strip()[:100]}")
    out += [f"{a[0]}: JSON_PARSE_ALLOWED lists '{a[1]}', which is no longer there: remove it from "
            "scripts/check-architecture.py" for a in JSON_PARSE_ALLOWED if a not in used]
    return out


def main():
    if "--table" in sys.argv:   # the folders' dependencies as the includes give them (a before/after count)
        for short, (folder, found) in sorted(derived(modules()).items()):
            print(f"{folder:14} {len(found):2}  {', '.join(sorted(found)) or 'nothing'}")
        return 0
    if "--writers" in sys.argv:
        files = sorted({f for f, _, _ in model_writers()})
        for f in files:
            print(f)
        print(f"{len(files)} file(s) outside src/store hold a writable store::Model")
        return 0
    mods = modules()
    code = derived(mods)
    doc = documented(mods)
    problems = []
    shorts = set(mods.values())
    for short, (folder, found) in sorted(code.items()):
        if short not in doc:
            problems.append(f"{folder}: no row in the module table of docs/ARCHITECTURE.md")
            continue
        for name in sorted(doc[short] - shorts):
            problems.append(f"{folder}: the table names '{name}', which is neither a folder nor a known library")
        for name in sorted(set(found) - doc[short]):
            problems.append(f"{folder}: depends on {name} ({found[name]}) but the table does not say so")
        for name in sorted((doc[short] & shorts) - set(found)):
            problems.append(f"{folder}: the table says it depends on {name}, but no file in it includes {name}/")
    problems += [f"folders include one another: {c}" for c in cycles(code)]
    problems += [f"{f}:{n}: a writable store::Model outside its owner (store/owner.h): {t}"
                 for f, n, t in model_writers()]
    door = json_parse_outside_door()
    if door:
        print("JSON from outside is parsed only through json_limits::parse_bounded:")
        for p in door:
            print("  " + p)
    if problems:
        print("docs/ARCHITECTURE.md's module table disagrees with the includes:")
        for p in problems:
            print("  " + p)
        return 1
    if door:
        return 1
    print(f"module table matches the includes of {len(code)} folders; only the owner writes the model; "
          "JSON parsed through the one door")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env bash
# Checks a stage's name map (its names.md): every C++ name in backquotes in the second
# column ("ours") is in one of the files the third column ("in") names, and those files
# exist. A file name in the second column (core.h) must be a file of the stage.
# A qualified name (Core::width, world.gravity) passes when it is there as written or
# when each of its parts is.
#
# usage: check_name_map.sh STAGE_FOLDER            the map passes: exit 0, else 1
#        check_name_map.sh --mutated STAGE_FOLDER  the checker can fail: every name of
#            the map, each changed by two letters, must then be reported missing (exit
#            0 when all of them are, else 1)
# Each problem is one line naming the map's row and the name.
#
# One pass in Python, each file read once: the check runs for every stage in every test
# run, and a grep per name (some 120 a map) cost seconds a stage on a busy machine.
exec python3 - "$@" <<'PYTHON'
import os
import re
import sys

arguments = sys.argv[1:]
mutate = bool(arguments) and arguments[0] == "--mutated"
if mutate:
    arguments = arguments[1:]
if not arguments:
    print("usage: check_name_map.sh [--mutated] STAGE_FOLDER", file=sys.stderr)
    sys.exit(1)
folder = arguments[0]
map_path = f"{folder}/names.md"
if not os.path.isfile(map_path):
    print(f"{map_path}: no such file")
    sys.exit(1)

WORD = re.compile(r"\w", re.ASCII)
texts = {}  # path -> its text, None when it cannot be read


def text_of(path):
    if path not in texts:
        try:
            with open(path, encoding="utf-8", errors="replace") as file:
                texts[path] = file.read()
        except OSError:
            texts[path] = None
    return texts[path]


def has_word(text, name):
    """`name` in `text` with no letter, digit or _ either side of it (grep -wF)."""
    start = text.find(name)
    while start != -1:
        end = start + len(name)
        before_ok = start == 0 or not WORD.match(text[start - 1])
        after_ok = end == len(text) or not WORD.match(text[end])
        if before_ok and after_ok:
            return True
        start = text.find(name, start + 1)
    return False


def found_in(name, paths):
    """`name` in one of the files: as written, or each of its parts."""
    readable = [text for text in map(text_of, paths) if text is not None]
    if any(has_word(text, name) for text in readable):
        return True
    parts = name.replace("::", " ").replace(".", " ").split()
    return all(any(has_word(text, part) for text in readable) for part in parts)


def mutated(name):
    """A name as the map writes it, changed so that it can be nowhere: Zq after its last
    part, or before a file name's extension."""
    match = re.fullmatch(r"(.*)(\.(h|cpp|json))", name)
    return f"{match[1]}Zq{match[2]}" if match else f"{name}Zq"


def quoted(cell):
    return re.findall(r"`([^`]*)`", cell)


checked = missing = 0
with open(map_path, encoding="utf-8") as map_file:
    for line_number, line in enumerate(map_file.read().splitlines(), start=1):
        if not line.startswith("| ") or line.startswith("| book |") or line.startswith("| --- "):
            continue
        cells = line.split("|", 4) + [""] * 4
        ours, where = cells[2], cells[3]

        def report(problem):  # one line a problem; the --mutated run counts them only
            if not mutate:
                print(f"{map_path}:{line_number}: {problem}")

        paths = []
        for file_name in quoted(where):
            path = f"{folder}/{file_name}"
            if not os.path.isfile(path):
                report(f"the file `{file_name}` is not there")
                missing += 1
            paths.append(path)
        for name in quoted(ours):
            if not name:
                continue
            if mutate:
                name = mutated(name)
            checked += 1
            if re.search(r"\.(h|cpp|json)$", name):
                if os.path.isfile(f"{folder}/{name}"):
                    continue
                report(f"`{name}` is no file of the stage")
            else:
                if found_in(name, paths):
                    continue
                report(f"`{name}` is not in{re.sub(' +', ' ', where.replace('`', ''))}")
            missing += 1

if mutate:
    if checked > 0 and missing == checked:
        print(f"every one of the {checked} names, changed, is reported missing")
        sys.exit(0)
    print(f"FAILED: only {missing} of the {checked} changed names are reported missing")
    sys.exit(1)
if checked == 0:
    print(f"{map_path}: no names in backquotes to check")
    sys.exit(1)
if missing > 0:
    print(f"FAILED: {missing} of the {checked} names of {map_path} are not where it says")
    sys.exit(1)
print(f"all {checked} names of {map_path} are where it says")
PYTHON

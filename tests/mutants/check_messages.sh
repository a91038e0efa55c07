#!/usr/bin/env bash
# Do the failures a reader meets teach? Each planted bug of tests/mutants/ is a mistake a
# reader could make, and what the failing tests print about it is what that reader
# reads. Every failed assertion must give its quantity, in the book's terms, with the
# value expected and the value got: Catch's own expansion of a comparison ("2 == 0",
# "false", "{?} == {?}") says none of that, unless a message names it.
#
# usage: MUTANTS_MESSAGES=DIR tools/mutants [stage...]    (keeps each mutant's output)
#        tests/mutants/check_messages.sh DIR               (exit 1 when a failure is mute)
# Each mute failure is printed with the mutant, the assertion and its file and line.
exec python3 - "$@" <<'PYTHON'
import os
import re
import sys

if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
    print("usage: check_messages.sh DIR   (DIR: MUTANTS_MESSAGES of a tools/mutants run)", file=sys.stderr)
    sys.exit(2)
top = sys.argv[1]

NUMBER = r"-?[0-9][0-9.e+-]*"
VALUE = (r"(" + NUMBER + r"|true|false|nan|-?inf|'.'|\{\?\}|0x[0-9a-f]+|Approx\( " + NUMBER + r" \)"
         r"|\(" + NUMBER + r", " + NUMBER + r"\)|\(\d+, \d+, \d+(, alpha \d+)?\)( [a-z]+)?)")
BARE = re.compile(r"^\s*" + VALUE + r"(\s+(==|!=|<|>|<=|>=)\s+" + VALUE + r")?\s*$")
mute = 0
failures = 0
for stage in sorted(os.listdir(top)):
    for name in sorted(os.listdir(os.path.join(top, stage)), key=lambda n: int(n.split(".")[0]) if n[0].isdigit() else 0):
        path = os.path.join(top, stage, name)
        with open(path, encoding="utf-8", errors="replace") as file:
            lines = file.read().split("\n")
        mutant = lines[0]
        i = 0
        while i < len(lines):
            line = lines[i]
            if not line.rstrip().endswith("FAILED:"):
                i += 1
                continue
            failures += 1
            where = line.strip()
            # The block: the assertion, then "with expansion:", "with message:" ... up to a blank line.
            block = []
            i += 1
            while i < len(lines) and lines[i].strip() != "":
                block.append(lines[i])
                i += 1
            text = "\n".join(block)
            has_message = "with message" in text or "with messages" in text
            expansion = []
            if "with expansion:" in text:
                after = text.split("with expansion:", 1)[1].split("\nwith message", 1)[0]
                expansion = [l for l in after.split("\n") if l.strip()]
            problem = None
            if "{?}" in text:
                problem = "prints {?}"
            elif not has_message and expansion and all(BARE.match(l) for l in expansion):
                problem = "a bare " + " ".join(l.strip() for l in expansion)
            elif not has_message and not expansion and block and re.search(r"\b(REQUIRE|CHECK)\(", block[0]):
                problem = "no expansion and no message"
            if problem:
                mute += 1
                assertion = block[0].strip() if block else "?"
                print(f"{stage}/{name}: {mutant[8:] if mutant.startswith('mutant: ') else mutant}\n"
                      f"  {where} {assertion}: {problem}")
print(f"check_messages: {mute} of {failures} failed assertions say no quantity", file=sys.stderr)
sys.exit(1 if mute else 0)
PYTHON

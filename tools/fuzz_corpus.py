#!/usr/bin/env python3
"""Seeds and dictionary for the scene fuzz target (make fuzz).

    tools/fuzz_corpus.py SEED_DIR DICTIONARY

SEED_DIR gets one file per seed: every scene and include file of the project (scenes/,
pov_includes/, tests/scene/data/), every input in tests/fuzz/crashes/, and every scene
snippet of the tests (the C++ string literals of tests/**/*_test.cpp that look like scene
text, adjacent literals joined).  DICTIONARY gets the words of the scene language in
libFuzzer's format: the reserved words of src/scene/keywords.cpp, the directives, the
Mirage_ settings of src/load/atmosphere_settings.cpp and the punctuation.
"""
import hashlib
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

DIRECTIVES = ["declare", "local", "undef", "include", "if", "ifdef", "ifndef", "elseif",
              "else", "switch", "case", "range", "break", "while", "for", "end", "macro",
              "version", "debug", "warning", "error", "default"]
PUNCTUATION = ["{", "}", "(", ")", "[", "]", "<", ">", "<=", ">=", "=", "!=", ",", ";", ".",
               "+", "-", "*", "/", "!", "?", ":", "&", "|", "#", "\""]


def cpp_string_literals(source):
    """The string literals of C++ source, adjacent ones joined, escapes processed."""
    out, current, i, n = [], None, 0, len(source)
    escapes = {"n": "\n", "t": "\t", "r": "\r", "\\": "\\", "\"": "\"", "'": "'", "0": "\0"}
    while i < n:
        c = source[i]
        if source.startswith("//", i):
            i = source.find("\n", i)
            i = n if i < 0 else i
            continue
        if source.startswith("/*", i):
            i = source.find("*/", i + 2)
            i = n if i < 0 else i + 2
            continue
        if c == "'":  # a character literal: skip it
            j = i + 1
            while j < n and source[j] != "'":
                j += 2 if source[j] == "\\" else 1
            i = j + 1
            continue
        if source.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', source[i:])
            if m:
                end = source.find(")" + m.group(1) + '"', i + m.end())
                if end >= 0:
                    text = source[i + m.end():end]
                    current = (current or "") + text
                    i = end + len(m.group(1)) + 2
                    continue
        if c == '"':
            j, text = i + 1, []
            while j < n and source[j] != '"':
                if source[j] == "\\" and j + 1 < n:
                    e = source[j + 1]
                    if e == "x":
                        m = re.match(r"[0-9a-fA-F]{1,2}", source[j + 2:])
                        text.append(chr(int(m.group(0), 16)) if m else "x")
                        j += 2 + (len(m.group(0)) if m else 0)
                        continue
                    text.append(escapes.get(e, e))
                    j += 2
                    continue
                text.append(source[j])
                j += 1
            current = (current or "") + "".join(text)
            i = j + 1
            continue
        if not c.isspace() and current is not None:
            out.append(current)
            current = None
        i += 1
    if current is not None:
        out.append(current)
    return out


def looks_like_scene(text):
    return len(text) >= 12 and any(ch in text for ch in "{#;")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    seed_dir, dictionary = sys.argv[1], sys.argv[2]
    os.makedirs(seed_dir, exist_ok=True)
    seeds = []
    for folder in ["scenes", "pov_includes", "tests/scene/data", "tests/fuzz/crashes"]:
        for base, _, names in os.walk(os.path.join(ROOT, folder)):
            for name in sorted(names):
                if name.endswith((".pov", ".inc")):
                    with open(os.path.join(base, name), "rb") as f:
                        seeds.append(f.read())
    for base, _, names in os.walk(os.path.join(ROOT, "tests")):
        for name in sorted(names):
            if name.endswith("_test.cpp"):
                with open(os.path.join(base, name), encoding="utf-8") as f:
                    for text in cpp_string_literals(f.read()):
                        if looks_like_scene(text):
                            seeds.append(text.encode("utf-8", "surrogateescape"))
    written = 0
    for data in seeds:
        path = os.path.join(seed_dir, hashlib.sha1(data).hexdigest())
        if not os.path.exists(path):
            with open(path, "wb") as f:
                f.write(data)
            written += 1

    with open(os.path.join(ROOT, "src/scene/keywords.cpp"), encoding="utf-8") as f:
        words = re.findall(r'^\s*"([a-z_0-9]+)",', f.read(), re.M)
    with open(os.path.join(ROOT, "src/load/atmosphere_settings.cpp"), encoding="utf-8") as f:
        words += sorted(set(re.findall(r'"(Mirage_[A-Za-z_0-9]+)"', f.read())))
    words += ["#" + d for d in DIRECTIVES] + PUNCTUATION
    with open(dictionary, "w", encoding="utf-8") as f:
        for w in dict.fromkeys(words):
            f.write('"' + w.replace("\\", "\\\\").replace('"', '\\"') + '"\n')
    print(f"{seed_dir}: {len(seeds)} seeds ({written} new); {dictionary}: {len(words)} words")


if __name__ == "__main__":
    main()

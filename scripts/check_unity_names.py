#!/usr/bin/env python3
"""Checks that no two files of one unity-built library declare the same name file-locally.

A unity build (RPT_UNITY_BUILD, cmake/RptHelpers.cmake) compiles a library's files in batches, each
batch one translation unit: two files' anonymous-namespace or `static` names then meet. The same
name declared twice is a compile error today, but batches change as files are added, and two
functions of one name with different parameters would silently become overloads of each other.
So every file-local name must be unique within its library, whatever the batches.

usage: check_unity_names.py DIR   (DIR holds one <library>.txt per unity-built library, written by
CMake: the library's source folder on the first line, then its sources, one per line)

Reads declarations at the start of a line (the project's clang-format style): functions, types,
constants, variables and type aliases inside `namespace {` ... `}  // namespace` (and inside a
file's own `namespace <file>_internal`, which a `using namespace` makes visible to the rest of its
batch), and `static` ones at namespace scope. Two aliases of the same type are allowed (the language allows them).
"""
import collections
import os
import re
import sys

FUNCTION = re.compile(r'^(?:template\s*<[^>]*>\s*)?(?:(?:static|inline|constexpr)\s+)*'
                      r'[A-Za-z_][\w:<>,\s\*&]*?[\s\*&]([A-Za-z_]\w*)\s*\(')
TYPE = re.compile(r'^(?:struct|class|enum(?:\s+class)?|union)\s+([A-Za-z_]\w*)\b(?!\s*;)')
CONSTANT = re.compile(r'^(?:static\s+)?(?:inline\s+)?(?:constexpr|const)\s+[\w:<>,\s\*&]*?\b([A-Za-z_]\w*)\s*'
                      r'(?:\[[^\]]*\])*\s*(?:=|\{)')
ALIAS = re.compile(r'^using\s+([A-Za-z_]\w*)\s*=\s*(.*);')
NOT_NAMES = {'if', 'for', 'while', 'return', 'switch', 'operator', 'sizeof'}


def file_local_names(path):
    """(kind, name, detail) of each file-local declaration of `path`."""
    names = []
    in_anonymous = False
    with open(path, encoding='utf-8', errors='replace') as f:
        for line in f:
            if re.match(r'^namespace(\s+\w+_internal)?\s*\{', line):
                in_anonymous = True
                continue
            if re.match(r'^\}\s*//\s*namespace(\s+\w+_internal)?\s*$', line):
                in_anonymous = False
                continue
            if not (in_anonymous or line.startswith('static ')):
                continue
            if line[:1] in (' ', '\t', '/', '#', '}', '\n'):
                continue
            line = re.sub(r'^(\[\[[^\]]*\]\]\s*)+', '', line)
            if m := ALIAS.match(line):
                names.append(('alias', m.group(1), m.group(2).strip()))
            elif m := TYPE.match(line):
                names.append(('type', m.group(1), ''))
            elif m := CONSTANT.match(line):
                names.append(('constant', m.group(1), ''))
                # Further declarators of the line (`constexpr int kMin = 0, kMax = 9;`).
                for other in re.findall(r',\s*([A-Za-z_]\w*)\s*=', line):
                    names.append(('constant', other, ''))
            elif (m := FUNCTION.match(line)) and m.group(1) not in NOT_NAMES:
                names.append(('function', m.group(1), ''))
    return names


def clashes(library, folder, sources):
    declared = collections.defaultdict(list)  # name -> [(file, kind, detail)]
    for source in sources:
        path = source if os.path.isabs(source) else os.path.join(folder, source)
        if not path.endswith(('.cc', '.cpp', '.cxx')):
            continue
        for kind, name, detail in file_local_names(path):
            declared[name].append((os.path.relpath(path, folder), kind, detail))
    found = []
    for name, places in sorted(declared.items()):
        if len({p[0] for p in places}) < 2:
            continue
        if all(p[1] == 'alias' for p in places) and len({p[2] for p in places}) == 1:
            continue
        found.append(f'{library}: {name} is declared file-locally in ' +
                     ', '.join(f'{p[0]} ({p[1]})' for p in places))
    return found


def main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        print(__doc__.split('\n\n')[2], file=sys.stderr)
        return 2
    found, libraries = [], 0
    for entry in sorted(os.listdir(sys.argv[1])):
        if not entry.endswith('.txt'):
            continue
        with open(os.path.join(sys.argv[1], entry), encoding='utf-8') as f:
            lines = [line.strip() for line in f if line.strip()]
        if not lines:
            continue
        libraries += 1
        found += clashes(entry[:-4], lines[0], lines[1:])
    if libraries == 0:
        print(f'no library source lists in {sys.argv[1]}', file=sys.stderr)
        return 2
    for line in found:
        print(line)
    if found:
        print(f'{len(found)} file-local name(s) declared in more than one file of a unity-built library: '
              'rename them (or share one definition in a header)', file=sys.stderr)
        return 1
    print(f'{libraries} unity-built libraries: every file-local name is declared in one file')
    return 0


if __name__ == '__main__':
    sys.exit(main())

#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks that the rpt commands quoted in README.md, docs/ and python/ still parse.

Every `rpt SUBCOMMAND ...` in a code span or a fenced code block is checked against the binary:
each --flag must be one that `rpt SUBCOMMAND --help` (or the nested subcommand's help, e.g.
`rpt cameras convert`) lists, and each `--set KEY=VALUE` key must be an option that `rpt config`
prints. Prints every mismatch as FILE:LINE and exits 1 when there is any.

Usage: check_doc_commands.py --rpt BUILD/rpt --root SOURCE_DIR
"""
import argparse
import json
import pathlib
import re
import subprocess
import sys

FLAG = re.compile(r"(?<![\w-])(--[a-z0-9][a-z0-9-]*)")
SUBCOMMAND_LINE = re.compile(r"^\s{2}([a-z][a-z0-9-]*)\s{2,}")
PLACEHOLDER_KEYS = {"section.key"}  # how the docs write "any option"


def help_text(rpt, words):
    return subprocess.run([rpt, *words, "--help"], capture_output=True, text=True, check=True).stdout


def subcommands(text):
    if "Subcommands:" not in text:
        return []
    names = []
    for line in text.split("Subcommands:", 1)[1].splitlines():
        match = SUBCOMMAND_LINE.match(line)
        if match:
            names.append(match.group(1))
    return names


class Cli:
    """The flags of every (nested) subcommand, read from the binary's help."""

    def __init__(self, rpt):
        top = help_text(rpt, [])
        self.global_flags = set(FLAG.findall(top.split("Subcommands:", 1)[0]))
        self.flags = {}
        self.nested = {}
        for name in subcommands(top):
            text = help_text(rpt, [name])
            self.flags[(name,)] = set(FLAG.findall(text)) | self.global_flags
            self.nested[name] = subcommands(text)
            for child in self.nested[name]:
                self.flags[(name, child)] = set(FLAG.findall(help_text(rpt, [name, child]))) | self.global_flags
        config = json.loads(subprocess.run([rpt, "config"], capture_output=True, text=True, check=True).stdout)
        self.option_keys = {f"{section}.{key}" for section, options in config.items() for key in options}

    def command(self, words):
        """The subcommand path that `words` (after `rpt`) names, or None."""
        if not words or (words[0],) not in self.flags:
            return None
        if len(words) > 1 and words[1] in self.nested.get(words[0], []):
            return (words[0], words[1])
        return (words[0],)


def quoted_commands(text):
    """(line number, text) of every fenced code block line and every code span (which may run over
    a line break) outside the blocks."""
    lines = text.splitlines(keepends=True)
    prose = []  # the lines outside fenced blocks, others blanked (line numbers stay)
    in_block = False
    for number, line in enumerate(lines, start=1):
        if line.lstrip().startswith("```"):
            in_block = not in_block
            prose.append("\n")
        elif in_block:
            yield number, line
            prose.append("\n")
        else:
            prose.append(line)
    joined = "".join(prose)
    for match in re.finditer(r"`([^`]+)`", joined):
        yield joined.count("\n", 0, match.start()) + 1, match.group(1).replace("\n", " ")


def check_file(cli, path, root, counts):
    """The problems of one Markdown file, as "FILE:LINE: what"; counts the commands and options seen."""
    problems = []
    text = path.read_text(encoding="utf-8")
    for number, snippet in quoted_commands(text):
        where = f"{path.relative_to(root)}:{number}"
        # One command per `rpt` occurrence, up to a shell separator or the next `rpt`.
        for match in re.finditer(r"(?:^|[\s(/])rpt\s+((?:(?!\brpt\s)[^|;&])*)", snippet):
            words = [w.strip("[]") for w in match.group(1).split()]
            command = cli.command(words)
            if command is None:
                continue
            counts["commands"] += 1
            known = cli.flags[command]
            for flag in FLAG.findall(" ".join(words)):
                if flag not in known:
                    problems.append(f"{where}: `rpt {' '.join(command)}` has no option {flag}")
        # Every option set on a command line, with or without `rpt` in the same quote.
        for match in re.finditer(r"--set\s+['\"]?([a-z_0-9]+\.[a-z_0-9]+)=", snippet):
            counts["set"] += 1
            if match.group(1) not in cli.option_keys | PLACEHOLDER_KEYS:
                problems.append(f"{where}: --set {match.group(1)}: no such option (see `rpt config`)")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rpt", required=True, help="the rpt binary")
    parser.add_argument("--root", required=True, help="the source tree (README.md, docs/, python/)")
    args = parser.parse_args()
    root = pathlib.Path(args.root).resolve()
    cli = Cli(args.rpt)
    files = [root / "README.md", *sorted((root / "docs").rglob("*.md")), *sorted((root / "python").rglob("*.md"))]
    counts = {"commands": 0, "set": 0}
    problems = [p for f in files if f.is_file() for p in check_file(cli, f, root, counts)]
    for problem in problems:
        print(problem)
    print(f"{len(files)} files, {counts['commands']} commands, {counts['set']} --set options checked: "
          f"{len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

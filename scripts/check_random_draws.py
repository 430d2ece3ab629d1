#!/usr/bin/env python3
"""Checks that no expression draws two random numbers whose order the language leaves open.

The synthetic data must be the same whatever the compiler (datasets/synthetic/random.h). The
arguments of one call, and the operands of one arithmetic operator, are evaluated in an
unspecified order (GCC evaluates a call's arguments last first, clang first first), so
`Eigen::Vector2d(rng.Normal(), rng.Normal())` or `rng.Normal() + rng.Normal()` draws different
numbers per compiler. Draws in separate statements or declarators, in the condition and the body
of an `if`, in a braced list, or in the branches of `?:` (and of `&&` / `||`) are sequenced and
allowed.

usage: check_random_draws.py FILE_OR_DIR...   (C++ sources; exit 1 and one line per finding)
       check_random_draws.py --self-test      (the checker on its own cases)
"""
import os
import re
import sys

DRAW = re.compile(r'\b\w+(?:\.|->)(?:Normal|Uniform|UniformInt|Bernoulli|Poisson|Gamma|Beta|StudentScale|NextBits)\(')
SEQUENCING = re.compile(r'\?|:|&&|\|\|')


def strip(text):
    """Comments and string literals blanked (same length, newlines kept)."""
    out = re.sub(r'//[^\n]*', lambda m: ' ' * len(m.group(0)), text)
    out = re.sub(r'/\*.*?\*/', lambda m: re.sub(r'[^\n]', ' ', m.group(0)), out, flags=re.S)
    return re.sub(r'"(?:\\.|[^"\\\n])*"', lambda m: ' ' * len(m.group(0)), out)


CONTROL = re.compile(r'\b(?:if|while|for|switch)\s*$')


def findings(text):
    """(offset, offset) of pairs of draws in one statement that nothing sequences."""
    code = strip(text)
    draws = [m.start() for m in DRAW.finditer(code)]
    draw_set = set(draws)
    where = {}  # draw -> (statement start, stack of the open parentheses around it)
    stack = []
    statement_start = 0
    for i, c in enumerate(code):
        if c in ';{}':
            stack = []
            statement_start = i + 1
        if i in draw_set:
            where[i] = (statement_start, tuple(stack))
        if c == '(':
            stack.append(i)
        elif c == ')' and stack:
            stack.pop()
    result = []
    for x, a in enumerate(draws):
        for b in draws[x + 1:]:
            if where[a][0] != where[b][0]:
                break  # later draws are in later statements
            stack_a, stack_b = where[a][1], where[b][1]
            common = 0
            while common < min(len(stack_a), len(stack_b)) and stack_a[common] == stack_b[common]:
                common += 1
            # a in the condition of an if/while/for/switch whose body holds b: sequenced.
            if len(stack_a) > common and CONTROL.search(code[where[a][0]:stack_a[common]]):
                continue
            # The text between them at the level of their innermost common group.
            depth, between = 0, []
            for j in range(a, b):
                if code[j] == '(':
                    depth += 1
                elif code[j] == ')':
                    depth -= 1
                elif depth <= 0:
                    between.append(code[j])
            text_between = ''.join(between).replace('::', '')
            # Outside any parentheses a comma ends a declarator or is the comma operator:
            # sequenced (so is a braced list, which starts a statement level of its own here).
            if common == 0 and ',' in text_between:
                continue
            if SEQUENCING.search(text_between):
                continue
            result.append((a, b))
    return result


# The checker's own cases: (source line, flagged?).
SELF_TEST = [
    ('error = Eigen::Vector2d(rng.Normal(), rng.Normal()) * sigma;', True),
    ('double a = rng.Normal() + rng.Normal();', True),
    ('g(h(rng.Normal()), rng.Uniform());', True),
    ('const double y = rng.Normal(), x = rng.Normal();', False),
    ('double b = ok ? rng.Uniform() : rng.Uniform();', False),
    ('if (rng.Bernoulli(0.5)) x = rng.Uniform(1, 2);', False),
    ('auto v = Vec{rng.Normal(), rng.Normal()};', False),
    ('bool c = rng.Bernoulli(0.1) && rng.Bernoulli(0.2);', False),
    ('// Vector2d(rng.Normal(), rng.Normal()) in a comment', False),
    ('x = rng.Normal();\ny = rng.Normal();', False),
]


def self_test():
    failed = 0
    for source, flagged in SELF_TEST:
        got = bool(findings('void f(Rng& rng) {\n' + source + '\n}\n'))
        if got != flagged:
            print(f'self-test: {source!r} flagged={got}, expected {flagged}')
            failed += 1
    return 1 if failed else 0


def main(paths):
    files = []
    for path in paths:
        if os.path.isdir(path):
            for root, _, names in os.walk(path):
                files += [os.path.join(root, n) for n in names if n.endswith(('.cc', '.h'))]
        else:
            files.append(path)
    bad = 0
    for path in sorted(files):
        text = open(path, encoding='utf-8').read()
        for a, _ in findings(text):
            line = text.count('\n', 0, a) + 1
            print(f'{path}:{line}: two random draws in one expression: their order depends on the compiler; '
                  'draw into variables (datasets/synthetic/random.h)')
            bad += 1
    return 1 if bad else 0


if __name__ == '__main__':
    if sys.argv[1:] == ['--self-test']:
        sys.exit(self_test())
    sys.exit(main(sys.argv[1:] or ['datasets/synthetic', 'bench']))

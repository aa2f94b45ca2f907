#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# No tracked .h/.cpp outside tests/ is over 500 lines, and no function body in one is over 80.
#
# Usage: sizes.py REPO_ROOT [--max-file N] [--max-function N]
# Reads the files `git ls-files` lists (so no folder is skipped), skips tests/, and prints one
# line per problem, `path:line: ...`; exits 1 when there is any. A function listed in EXEMPT
# (path and first line of the definition text) is reported as a note instead, with its reason.
#
# Function bodies are found by a brace-matching heuristic meant for clang-formatted code:
#   - comments, string and character literals (raw strings included) are blanked first, so
#     braces inside them do not count;
#   - a definition starts at a line that ends in `{`, outside any function body, whose text
#     holds `(` or `)` (a wrapped signature ends in `)`), and that is not a
#     control statement (if/for/while/switch/else/do/try/catch) nor a namespace, class, struct,
#     union or enum head;
#   - the body runs to the line where the brace depth falls back; its length is the number of
#     lines strictly between the opening and the closing brace line. Lambdas and local classes
#     count inside their enclosing function; methods defined in a class body count on their own.
# Limits: a definition whose `{` stands alone on its own line, or a brace initialiser at
# namespace scope that happens to hold a parenthesis (`const X k = make(a, {`), is treated
# per the rules above and may be missed or miscounted; macros that open or close braces
# unevenly confuse the depth; code outside clang-format's style (several definitions on one
# line) is measured by lines, not statements.
import re
import subprocess
import sys

MAX_FILE = 500
MAX_FUNCTION = 80
# Long functions left for now, each with the reason; a stale entry is reported as a note.
# Empty: every function outside tests/ is within the limit.
EXEMPT = {}
CONTROL = re.compile(r'^\s*(\}\s*)?(if|for|while|switch|else|do|try|catch)\b')
SCOPE_HEAD = re.compile(r'^\s*((template\s*<.*>\s*)?(namespace|class|struct|union|enum)\b'
                        r'|extern\s+"C")')


def blank(text):
    """Returns |text| with comments and literals replaced by spaces, newlines kept."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith('//', i):
            j = text.find('\n', i)
            j = n if j < 0 else j
            out.append(' ' * (j - i))
            i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i) and (i == 0 or not text[i - 1].isalnum()):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = text.find(')' + m.group(1) + '"', i)
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append('""' + re.sub(r'[^\n]', ' ', text[i + 2:j]))
            i = j
        elif c in '"\'':
            if c == "'" and i > 0 and text[i - 1].isalnum():  # digit separator 1'000
                out.append(' ')
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != '\n':
                j += 2 if text[j] == '\\' else 1
            j = min(j + 1, n)
            out.append(c + ' ' * (j - i - 2) + c if j - i >= 2 else c)
            i = j
        else:
            out.append(c)
            i += 1
    return ''.join(out)


def long_functions(text, limit):
    """Yields (line number, body lines) for each function body over |limit| lines."""
    lines = blank(text).split('\n')
    depth = 0
    start = None  # (line index, depth before its brace) of the function being measured
    for index, line in enumerate(lines):
        stripped = line.strip()
        if start is None and stripped.endswith('{'):
            if (('(' in stripped or ')' in stripped) and not CONTROL.match(stripped)
                    and not SCOPE_HEAD.match(stripped)
                    and not stripped.startswith(('=', '{'))):
                start = (index, depth)
        depth += line.count('{') - line.count('}')
        if start is not None and depth <= start[1]:
            body = index - start[0] - 1
            if body > limit:
                yield start[0] + 1, body
            start = None


def main(argv):
    root = argv[1]
    max_file = MAX_FILE
    max_function = MAX_FUNCTION
    rest = argv[2:]
    while rest:
        if rest[0] == '--max-file':
            max_file = int(rest[1])
        elif rest[0] == '--max-function':
            max_function = int(rest[1])
        else:
            print(f'unknown option {rest[0]}')
            return 2
        rest = rest[2:]
    listed = subprocess.run(['git', '-C', root, 'ls-files', '*.h', '*.cpp'], check=True,
                            capture_output=True, text=True).stdout.split()
    if not listed:
        print(f'no tracked sources under {root} (not a git checkout?)')
        return 1
    problems, notes, used = [], [], set()
    for path in listed:
        if path.startswith('tests/'):
            continue
        try:
            with open(f'{root}/{path}', encoding='utf-8', errors='replace') as f:
                text = f.read()
        except FileNotFoundError:
            continue  # deleted in the working tree
        count = text.count('\n') + (0 if text.endswith('\n') or not text else 1)
        if count > max_file:
            problems.append(f'{path}:1: file has {count} lines (over {max_file})')
        lines = text.split('\n')
        for line, body in long_functions(text, max_function):
            finding = f'{path}:{line}: function body has {body} lines (over {max_function})'
            reason = next((why for (where, head), why in EXEMPT.items()
                           if where == path and head in lines[line - 1]), None)
            if reason:
                used.add(path)
                notes.append(f'{finding}; exempt: {reason}')
            else:
                problems.append(finding)
    notes += [f'{where}: stale exemption for `{head}` (no longer needed)'
              for (where, head) in EXEMPT if where not in used]
    for note in notes:
        print(f'note: {note}')
    for problem in problems:
        print(problem)
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))

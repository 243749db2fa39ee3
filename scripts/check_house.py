#!/usr/bin/env python3
"""Checks the rules of the house (docs/architecture.md) on the source tree,
every file of every room, in its subfolders too: every project include names
its room and points to a room this room may include; no two files include
each other (a .cpp and its .hpp count as one unit); app/ holds only commands
and their option parsing (main.cpp, cmd_*.cpp, commands.hpp, *_options.*);
no test name in tests/ starts with "-"; no function in run/ is longer than
80 lines; no page of docs/ is longer than 200 lines or speaks of how the
project is worked on ("the issue", "helper").
Prints each breach; exit 1 if any. Usage: scripts/check_house.py [PROJECT_ROOT]"""
import os
import re
import sys

# The geometry kernel's rooms stand in core/; a room's name is its folder.
BELOW = {
    'core/base': set(), 'evolution': {'core/base'},
    'core/mesh': {'core/base'},
    'core/io': {'core/base', 'core/mesh'},
    'core/growth': {'core/base', 'core/mesh', 'core/io'},
    'fitness': {'core/base', 'core/mesh'},
}
BELOW['engine'] = BELOW['core/growth'] | {'core/growth'}
BELOW['run'] = BELOW['engine'] | {'engine', 'fitness', 'evolution'}
BELOW['cluster'] = BELOW['run'] | {'run'}
BELOW['report'] = BELOW['run'] | {'run'}
BELOW['breed'] = BELOW['report'] | {'report'}  # morphogen breed: run/ and below, report/'s renderer
BELOW['fuzz'] = BELOW['run'] | {'run'}
BELOW['app'] = BELOW['run'] | {'run', 'cluster', 'report', 'breed'}
BELOW['bench'] = {'evolution'}  # benchmarks beside the product: link it, never linked by it
SOURCE = ('.cpp', '.hpp', '.cpp.in')

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..')
breaches = []
units = {}  # unit -> units it includes
def room_of(target):
    """The room an include names: its longest leading folders that are a room."""
    parts = target.split('/')
    for n in range(len(parts) - 1, 0, -1):
        if '/'.join(parts[:n]) in BELOW:
            return '/'.join(parts[:n])
    return None


def sources(room):
    """Every source file of a room, its subfolders' too, as root-relative paths."""
    for folder, dirs, names in os.walk(os.path.join(root, room)):
        dirs[:] = sorted(d for d in dirs if d not in ('node_modules', 'assets'))
        rel = os.path.relpath(folder, root).replace(os.sep, '/')
        for name in sorted(names):
            if name.endswith(SOURCE):
                yield f'{rel}/{name}'


for room, below in BELOW.items():
    for path in sources(room):
        unit = path.split('.')[0]
        with open(os.path.join(root, path), encoding='utf-8') as f:
            for number, line in enumerate(f, 1):
                m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
                if not m:
                    continue
                target = m.group(1)
                target_room = room_of(target)
                if target_room not in BELOW:
                    breaches.append(f'{path}:{number}: include "{target}" does not name its room')
                elif target_room != room and target_room not in below:
                    breaches.append(f'{path}:{number}: {room}/ may not include {target_room}/ ("{target}")')
                units.setdefault(unit, set()).add(target.split('.')[0])
for unit, targets in sorted(units.items()):
    for other in sorted(targets):
        if other != unit and unit in units.get(other, ()) and unit < other:
            breaches.append(f'{unit} and {other} include each other')
APP_FILE = re.compile(r'(main\.cpp|commands\.hpp|cmd_\w+\.cpp|\w+_options\.(cpp|hpp))$')
for path in sources('app'):
    if not APP_FILE.match(path[len('app/'):]):
        breaches.append(f'{path}: app/ holds only commands and their option parsing; move it into the room it belongs to')
# A function of run/ (the largest room) stays readable: at most 80 lines from
# its signature to its closing brace. A definition is found by the house's
# layout: its signature starts in column 0 and its body ends with a "}" alone
# in column 0.
MAX_FUNCTION_LINES = 80
NOT_A_FUNCTION = re.compile(r'(namespace|using|struct|class|enum|union|template|typedef|extern|static_assert)\b')
def long_functions(path, lines):
    start = None
    in_body = False
    for number, line in enumerate(lines, 1):
        text = line.rstrip()
        if not in_body:
            if start is None and re.match(r'[A-Za-z_]', text) and not NOT_A_FUNCTION.match(text) and '(' in text:
                start = number
            if start is not None:
                code = re.sub(r'//.*', '', text).rstrip()
                if code.endswith(';') or (code.endswith('}') and '{' in code):
                    start = None  # a declaration, or a body on one line
                elif code.endswith('{'):
                    in_body = True
        elif text == '}':
            if number - start + 1 > MAX_FUNCTION_LINES:
                yield f'{path}:{start}: a function of {number - start + 1} lines (run/ allows {MAX_FUNCTION_LINES})'
            start, in_body = None, False
for path in sources('run'):
    with open(os.path.join(root, path), encoding='utf-8') as f:
        breaches.extend(long_functions(path, f.readlines()))
# docs/ is for users: pages short enough to read, in the words of the product.
MAX_DOC_LINES = 200
WORKSHOP_WORDS = re.compile(r'\bthe issue\b|\bissues? #?\d+\b|\bhelpers?\b', re.IGNORECASE)
docs = os.path.join(root, 'docs')
for name in sorted(os.listdir(docs)) if os.path.isdir(docs) else []:
    if not name.endswith('.md'):
        continue
    with open(os.path.join(docs, name), encoding='utf-8') as f:
        lines = f.readlines()
    if len(lines) > MAX_DOC_LINES:
        breaches.append(f'docs/{name}: {len(lines)} lines (a page holds at most {MAX_DOC_LINES}; split it by subject)')
    for number, line in enumerate(lines, 1):
        if m := WORKSHOP_WORDS.search(line):
            breaches.append(f'docs/{name}:{number}: "{m.group(0)}" speaks of the work, not the product')
# A Catch2 test named "-..." is read as a command-line option when CTest runs it alone.
for folder, dirs, names in os.walk(os.path.join(root, 'tests')):
    for name in sorted(names):
        if name.endswith('.cpp'):
            path = os.path.join(folder, name)
            with open(path, encoding='utf-8') as f:
                for number, line in enumerate(f, 1):
                    if re.search(r'TEST_CASE\(\s*"-', line):
                        rel = os.path.relpath(path, root).replace(os.sep, '/')
                        breaches.append(f'{rel}:{number}: a test name may not start with "-" (Catch2 reads it as an option)')
for b in breaches:
    print(b)
print(f'house: {len(units)} units checked, {len(breaches)} breaches')
sys.exit(1 if breaches else 0)

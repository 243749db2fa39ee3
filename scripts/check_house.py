#!/usr/bin/env python3
"""Checks the rules of the house (docs/architecture.md) on the source tree:
every project include names its room and points to a room this room may
include; no two files include each other (a .cpp and its .hpp count as one
unit); app/ holds at most 15 source files. Prints each breach; exit 1 if any.
Usage: scripts/check_house.py [PROJECT_ROOT]"""
import os
import re
import sys

BELOW = {
    'base': set(), 'evolution': {'base'},
    'mesh': {'base'},
    'io': {'base', 'mesh'},
    'growth': {'base', 'mesh', 'io'},
    'fitness': {'base', 'mesh'},
}
BELOW['engine'] = BELOW['growth'] | {'growth'}
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
for room, below in BELOW.items():
    for name in sorted(os.listdir(os.path.join(root, room))):
        if not name.endswith(SOURCE):
            continue
        path = f'{room}/{name}'
        unit = path.split('.')[0]
        with open(os.path.join(root, path), encoding='utf-8') as f:
            for number, line in enumerate(f, 1):
                m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
                if not m:
                    continue
                target = m.group(1)
                target_room = target.split('/')[0] if '/' in target else None
                if target_room not in BELOW:
                    breaches.append(f'{path}:{number}: include "{target}" does not name its room')
                elif target_room != room and target_room not in below:
                    breaches.append(f'{path}:{number}: {room}/ may not include {target_room}/ ("{target}")')
                units.setdefault(unit, set()).add(target.split('.')[0])
for unit, targets in sorted(units.items()):
    for other in sorted(targets):
        if other != unit and unit in units.get(other, ()) and unit < other:
            breaches.append(f'{unit} and {other} include each other')
app_sources = [n for n in os.listdir(os.path.join(root, 'app')) if n.endswith('.cpp')]
if len(app_sources) > 15:
    breaches.append(f'app/ holds {len(app_sources)} source files, more than 15: move what is not a command into a room')
for b in breaches:
    print(b)
print(f'house: {len(units)} units checked, {len(breaches)} breaches')
sys.exit(1 if breaches else 0)

#!/usr/bin/env python3
"""The layering of core/, kept by the build: each folder named in FACETLIGHT_CORE_FOLDERS (core/CMakeLists.txt)
includes only itself and the folders listed before it, and no other folder's detail/ headers; every folder of
core/ is in the list, and core/ never includes the HTTP library.

Usage: layering_test.py CORE_DIR. Prints each upward include as FILE:LINE and exits 1 when there is one."""
import pathlib
import re
import sys

INCLUDE = re.compile(r'\s*#\s*include\s+[<"]([^>"]+)[>"]')


def core_folders(cmake_lists):
    text = cmake_lists.read_text()
    match = re.search(r'set\(FACETLIGHT_CORE_FOLDERS\s+([^)]*)\)', text)
    if not match:
        sys.exit(f'{cmake_lists}: no set(FACETLIGHT_CORE_FOLDERS ...)')
    return match.group(1).split()


def faults(core):
    folders = core_folders(core / 'CMakeLists.txt')
    rank = {name: i for i, name in enumerate(folders)}
    found = []
    for folder in sorted(p for p in core.iterdir() if p.is_dir()):
        if folder.name not in rank:
            found.append(f'core/{folder.name}/: not in FACETLIGHT_CORE_FOLDERS')
            continue
        for source in sorted(folder.rglob('*')):
            if source.suffix not in ('.h', '.cpp'):
                continue
            where = source.relative_to(core.parent)
            for number, line in enumerate(source.read_text().splitlines(), 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                target = match.group(1)
                top = target.split('/')[0]
                if top == 'httplib.h':
                    found.append(f'{where}:{number}: core includes the HTTP library')
                if top not in rank or top == folder.name:
                    continue
                if rank[top] > rank[folder.name]:
                    found.append(f'{where}:{number}: {folder.name}/ includes "{target}", a folder listed after it')
                elif '/detail/' in target:
                    found.append(f'{where}:{number}: {folder.name}/ includes "{target}", another folder\'s detail/')
    return found


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    found = faults(pathlib.Path(sys.argv[1]).resolve())
    for fault in found:
        print(fault)
    print(f'{len(found)} layering faults')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main())

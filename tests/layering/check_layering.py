#!/usr/bin/env python3
"""The layering rules of ../shared/DESIGN.md, checked on the include graph.

Every header and source file belongs to the layer of the folder it lives in. Its includes are
resolved the way the compiler resolves them (the file's own folder for "...", the layers'
include/ folders for <...>), whatever the headers are called, and followed transitively. A file
may reach only the layers its own layer may use:

    lie       Eigen
    iga       Eigen
    core      lie, iga                      (lib/model)
    elements  core and below                (lib/elements: the element families)
    output    core and below                (lib/output)
    joints    core and below                (joints/)
    solvers   joints, core and below        (solvers/)
    study     solvers, joints, output, core and below   (lib/study: a driver's command line and recording)

so the model, the output, the joints, the solvers and the study layer name no element kind. `base`
(include/spar/error.hpp) may be used by all; the umbrella include/spar/spar.hpp by none.

Usage: check_layering.py ROOT          checks the tree at ROOT, lists every broken rule
       check_layering.py --self-test   builds small trees that break each rule and checks that
                                       every one is reported (the test can fail)
"""
import os
import re
import sys
import tempfile

# layer -> folders (relative to the root) whose files belong to it
LAYER_FOLDERS = {
    "base": ["include"],
    "lie": ["lie"],
    "iga": ["iga"],
    "core": ["lib/model"],
    "elements": ["lib/elements"],
    "output": ["lib/output"],
    "joints": ["joints"],
    "solvers": ["solvers"],
    "study": ["lib/study"],
}
# layer -> the layers it may reach (itself included)
ALLOWED = {
    "base": {"base"},
    "lie": {"base", "lie"},
    "iga": {"base", "iga"},
    "core": {"base", "lie", "iga", "core"},
    "elements": {"base", "lie", "iga", "core", "elements"},
    "output": {"base", "lie", "iga", "core", "output"},
    "joints": {"base", "lie", "iga", "core", "joints"},
    "solvers": {"base", "lie", "iga", "core", "joints", "solvers"},
    "study": {"base", "lie", "iga", "core", "output", "joints", "solvers", "study"},
}
UMBRELLA = os.path.join("include", "spar", "spar.hpp")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)


def layer_of(root, path):
    relative = os.path.relpath(path, root)
    for layer, folders in LAYER_FOLDERS.items():
        for folder in folders:
            if relative == folder or relative.startswith(folder + os.sep):
                return layer
    return None


def include_dirs(root):
    """Every include/ folder of every layer (the families have one each)."""
    dirs = []
    for folders in LAYER_FOLDERS.values():
        for folder in folders:
            for here, subdirs, _ in os.walk(os.path.join(root, folder)):
                if os.path.basename(here) == "include":
                    dirs.append(here)
                    subdirs[:] = []
    return dirs


def sources(root):
    for folders in LAYER_FOLDERS.values():
        for folder in folders:
            for here, _, files in os.walk(os.path.join(root, folder)):
                for name in files:
                    if name.endswith((".hpp", ".cpp", ".h")):
                        yield os.path.join(here, name)


def resolve(name, quoted, from_file, dirs):
    candidates = ([os.path.dirname(from_file)] if quoted else []) + dirs
    for folder in candidates:
        path = os.path.normpath(os.path.join(folder, name))
        if os.path.isfile(path):
            return path
    return None  # a system or third-party header


def violations(root):
    root = os.path.abspath(root)
    dirs = include_dirs(root)
    direct = {}
    for path in sources(root):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        direct[path] = [p for q, n in INCLUDE.findall(text) if (p := resolve(n, q == '"', path, dirs))]
    found = []
    for path in sorted(direct):
        if os.path.relpath(path, root) == UMBRELLA:
            continue
        own = layer_of(root, path)
        # Depth-first over the includes, remembering through which chain a header was reached.
        chain_to = {path: [path]}
        stack = [path]
        while stack:
            current = stack.pop()
            for header in direct.get(current, []):
                if header in chain_to:
                    continue
                chain_to[header] = chain_to[current] + [header]
                target = layer_of(root, header)
                if os.path.relpath(header, root) == UMBRELLA or target not in ALLOWED[own]:
                    chain = " -> ".join(os.path.relpath(p, root) for p in chain_to[header])
                    found.append(f"{own} may not use {target or 'the umbrella header'}: {chain}")
                    continue
                stack.append(header)
    return found


def self_test():
    """Each rule broken once in a small tree must be reported; the clean tree must pass."""
    def write(root, relative, text):
        path = os.path.join(root, relative)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)

    def tree(root, broken):
        write(root, "include/spar/error.hpp", "")
        write(root, "lib/model/include/spar/core/model.hpp", '#include <spar/error.hpp>\n')
        write(root, "lib/elements/beam/include/spar/elements/beam/beam.hpp", '#include <spar/core/model.hpp>\n')
        # An element kind reached through a header of an innocent name, two steps away.
        write(root, "lib/elements/beam/include/spar/core/helpers.hpp",
              '#include <spar/elements/beam/beam.hpp>\n')
        write(root, "lib/output/src/writer.cpp", '#include <spar/core/model.hpp>\n')
        write(root, "joints/src/joint.cpp", '#include <spar/core/model.hpp>\n')
        write(root, "solvers/src/solver.cpp", '#include "local.hpp"\n')
        write(root, "solvers/src/local.hpp", '#include <spar/core/model.hpp>\n')
        write(root, "lib/study/src/recorder.cpp", '#include "../../../solvers/src/local.hpp"\n#include "../../output/src/writer.cpp"\n')
        if broken:
            write(root, broken[0], broken[1])

    cases = [
        ("lib/model/src/model.cpp", '#include <spar/elements/beam/beam.hpp>\n', "core may not use elements"),
        ("lib/output/src/writer.cpp", '#include <spar/core/helpers.hpp>\n', "output may not use elements"),
        ("joints/src/joint.cpp", '#include <spar/elements/beam/beam.hpp>\n', "joints may not use elements"),
        ("solvers/src/local.hpp", '#include <spar/elements/beam/beam.hpp>\n', "solvers may not use elements"),
        ("lib/model/src/model.cpp", '#include "../../../solvers/src/local.hpp"\n', "core may not use solvers"),
        ("lib/study/src/recorder.cpp", '#include <spar/elements/beam/beam.hpp>\n', "study may not use elements"),
        ("solvers/src/local.hpp", '#include "../../lib/study/src/recorder.cpp"\n', "solvers may not use study"),
    ]
    failures = 0
    with tempfile.TemporaryDirectory() as root:
        tree(root, None)
        if violations(root):
            print("self-test: the clean tree was reported:", violations(root))
            failures += 1
    for relative, text, expected in cases:
        with tempfile.TemporaryDirectory() as root:
            tree(root, (relative, text))
            found = violations(root)
            if not any(v.startswith(expected) for v in found):
                print(f"self-test: '{expected}' not reported for {relative}; found {found}")
                failures += 1
    print(f"self-test: {len(cases)} broken trees, {failures} missed")
    return 1 if failures else 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    found = violations(sys.argv[1])
    for line in found:
        print(line)
    print(f"layering: {len(found)} broken rule(s)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())

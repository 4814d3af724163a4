#!/usr/bin/python3
"""Checks kinestat's layering (docs/architecture.md).

  core -> elements -> solver -> msa, vjm, fea (methods) -> mechanisms -> io -> cli

1. A public header (include/kinestat/L/) or a source/internal header (src/L/) includes public headers
   of its own layer or of layers below it only, and internal headers ("M/x.hpp" under src/M/) of
   its own layer only. Tests (tests/L/) and benchmarks may include internals: they are not checked
   for that, but tests/L may not include layers above L.
   A public header includes no internal header at all (it is installed; they are not).
2. A layer's CMakeLists.txt links exactly the kinestat layers its files include (no more: a layer
   links only the layers it includes).
3. The examples (examples/) and the install test's consumer (tests/install/) include public headers
   only: they use kinestat as an outside project does.
4. docs/architecture.md lists exactly the internal headers there are (src/L/x.hpp as `L/x`).

Usage: scripts/check_layers.py [ROOT]        exit 0 when clean, 1 with one line per violation
       scripts/check_layers.py --self-test   plants four faults in a copy of the tree and checks
                                             that each is caught (exit 0 when they are)
"""
import pathlib
import re
import shutil
import sys
import tempfile

# Each layer and the layers it may use (transitively closed).
BELOW = {
    "core": set(),
    "elements": {"core"},
    "solver": {"core"},
    "msa": {"core", "elements", "solver"},
    "vjm": {"core", "elements", "solver"},
    "fea": {"core", "elements", "solver"},
    "mechanisms": {"core", "elements", "solver", "msa", "vjm", "fea"},
    "io": {"core", "elements", "solver", "msa", "vjm", "fea", "mechanisms"},
    "cli": {"core", "elements", "solver", "msa", "vjm", "fea", "mechanisms", "io"},
    "python": {"core", "elements", "solver", "msa", "vjm", "fea", "mechanisms", "io"},
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
LINK = re.compile(r"kinestat_(\w+)")


def layer_files(root, layer):
    for base in (root / "include" / "kinestat" / layer, root / "src" / layer):
        if base.is_dir():
            yield from sorted(p for p in base.rglob("*") if p.suffix in (".hpp", ".cpp", ".h"))


def check(root):
    root = pathlib.Path(root)
    errors = []
    for layer, allowed in BELOW.items():
        used = set()
        for path in layer_files(root, layer):
            rel = path.relative_to(root)
            text = path.read_text(errors="replace")
            for m in INCLUDE.finditer(text):
                inc = m.group(1)
                line = text.count("\n", 0, m.start()) + 1
                parts = inc.split("/")
                if parts[0] == "kinestat" and len(parts) >= 3:
                    target = parts[1]
                    if target == layer:
                        continue
                    if target not in allowed:
                        errors.append(f"{rel}:{line}: layer '{layer}' includes '{inc}' from the higher "
                                      f"or unrelated layer '{target}'")
                    used.add(target)
                elif len(parts) >= 2 and parts[0] in BELOW:
                    if parts[0] != layer:
                        errors.append(f"{rel}:{line}: layer '{layer}' includes '{inc}', an internal header "
                                      f"of layer '{parts[0]}' (use a public header under include/kinestat/)")
                    elif rel.parts[0] == "include":
                        errors.append(f"{rel}:{line}: the public header includes the internal header '{inc}', "
                                      f"which is not installed (move what it needs to a public header)")
        cmake = root / "src" / layer / "CMakeLists.txt"
        if cmake.is_file():
            text = cmake.read_text()
            call = re.search(r"kinestat_layer\(\s*" + layer + r"\b(.*?)\)", text, re.S)
            if call:
                linked = {name for name in LINK.findall(call.group(1)) if name in BELOW} - {layer}
                # Transitive links are fine for what the layer does not include itself: require
                # that every included layer is reachable and that no directly linked layer is unused.
                for extra in sorted(linked - used):
                    errors.append(f"src/{layer}/CMakeLists.txt: links kinestat_{extra} but includes none "
                                  f"of its headers")
                for target in sorted(linked - allowed):
                    errors.append(f"src/{layer}/CMakeLists.txt: links the higher layer kinestat_{target}")
    for tests in sorted((root / "tests").glob("*")):
        layer = tests.name
        if layer not in BELOW or not tests.is_dir():
            continue
        for path in sorted(p for p in tests.rglob("*") if p.suffix in (".hpp", ".cpp")):
            text = path.read_text(errors="replace")
            for m in INCLUDE.finditer(text):
                parts = m.group(1).split("/")
                target = parts[1] if parts[0] == "kinestat" and len(parts) >= 3 else None
                if target and target != layer and target not in BELOW[layer]:
                    line = text.count("\n", 0, m.start()) + 1
                    errors.append(f"{path.relative_to(root)}:{line}: tests of '{layer}' include the higher "
                                  f"layer '{target}' (move the test up to tests/{target}/)")
    for folder in (root / "examples", root / "tests" / "install"):
        for path in sorted(p for p in folder.rglob("*") if p.suffix in (".hpp", ".cpp")) if folder.is_dir() else []:
            text = path.read_text(errors="replace")
            for m in INCLUDE.finditer(text):
                parts = m.group(1).split("/")
                if len(parts) >= 2 and parts[0] in BELOW:
                    line = text.count("\n", 0, m.start()) + 1
                    errors.append(f"{path.relative_to(root)}:{line}: includes the internal header '{m.group(1)}'; "
                                  f"examples use public headers (kinestat/...) only")
    errors += check_internal_header_list(root)
    return errors


def check_internal_header_list(root):
    """docs/architecture.md lists every internal header (src/L/x.hpp as `L/x`) between its
    'internal headers' markers, and nothing else: the list a newcomer reads stays true."""
    doc = root / "docs" / "architecture.md"
    if not doc.is_file():
        return []
    text = doc.read_text()
    block = re.search(r"<!-- internal headers: begin -->(.*?)<!-- internal headers: end -->", text, re.S)
    if not block:
        return ["docs/architecture.md: the '<!-- internal headers: begin/end -->' list is missing"]
    listed = set(re.findall(r"^\|\s*`(\w+/\w+)`", block.group(1), re.M))
    present = {f"{p.parent.name}/{p.stem}" for p in (root / "src").glob("*/*.hpp")}
    errors = [f"docs/architecture.md: internal header src/{h}.hpp is not in the list of internal headers; add it"
              for h in sorted(present - listed)]
    errors += [f"docs/architecture.md: lists the internal header `{h}`, but src/{h}.hpp does not exist"
               for h in sorted(listed - present)]
    return errors


def self_test(root):
    """Plants an upward include, a cross-layer internal include, an internal include in a public
    header of the same layer and an internal header the architecture page does not list, in a copy;
    all four must be reported."""
    root = pathlib.Path(root)
    with tempfile.TemporaryDirectory() as tmp:
        copy = pathlib.Path(tmp) / "tree"
        for part in ("include", "src", "tests", "examples", "docs"):
            if (root / part).is_dir():
                shutil.copytree(root / part, copy / part)
        if check(copy):
            print("self-test: the unmodified tree already fails; fix that first")
            return 1
        target = copy / "src" / "msa" / "assembly.cpp"
        target.write_text('#include "kinestat/io/results_json.hpp"\n' + target.read_text())
        header = copy / "include" / "kinestat" / "mechanisms" / "five_bar.hpp"
        header.write_text(header.read_text().replace("#pragma once", '#pragma once\n#include "vjm/bordered_system.hpp"', 1))
        public = copy / "include" / "kinestat" / "msa" / "structure.hpp"
        public.write_text(public.read_text().replace("#pragma once", '#pragma once\n#include "msa/dof_map.hpp"', 1))
        (copy / "src" / "io" / "planted.hpp").write_text("#pragma once\n")
        errors = check(copy)
        upward = [e for e in errors if "src/msa/assembly.cpp:1:" in e and "higher" in e]
        internal = [e for e in errors if "five_bar.hpp" in e and "internal header" in e]
        installed = [e for e in errors if "msa/structure.hpp" in e and "not installed" in e]
        unlisted = [e for e in errors if "src/io/planted.hpp is not in the list" in e]
        if upward and internal and installed and unlisted and len(errors) == 4:
            print("self-test: the four planted faults caught:")
            for e in errors:
                print("  " + e)
            return 0
        print("self-test FAILED: planted faults not caught as expected; got:")
        for e in errors:
            print("  " + e)
        return 1


def main(argv):
    root = pathlib.Path(__file__).resolve().parent.parent
    if len(argv) > 1 and argv[1] == "--self-test":
        return self_test(root)
    if len(argv) > 1:
        root = pathlib.Path(argv[1])
    errors = check(root)
    for e in errors:
        print(e)
    if errors:
        print(f"check_layers: {len(errors)} violation(s)")
        return 1
    print("check_layers: layers and links are consistent")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

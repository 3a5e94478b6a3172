#!/usr/bin/env python3
"""The include graph of flexure's library folders (docs/architecture.md).

    python3 scripts/include_graph.py [--edges] [--cycles] [--file-cycles] [--public]

Reads every .h and .cpp of the library folders (solver/, elements/, beam/, mechanisms/, io/,
benchmarks/studies/, include/flexure/) and both include styles, "flexure/..." and <flexure/...>.
A file belongs to the folder it sits in (solver/shooting, mechanisms/cfm, io/platform, ...).

  --edges        folder -> folder edges with the number of includes and the including files
  --cycles       cycles between folders (strongly connected components of the folder graph) with
                 the includes that make them; exit 1 when there is one
  --file-cycles  cycles between files inside one folder
  --public       the headers <flexure/flexure.h> reaches (the installed closure, as
                 cmake/FlexureInstall.cmake computes it), per folder

Without options: --edges --cycles --public. Standard library only.
"""

import argparse
import collections
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LIBRARY = ["solver", "elements", "beam", "mechanisms", "io", "benchmarks/studies", "include/flexure"]
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])flexure/([^">]+)[">]')
# Generated in the build tree, not a source file.
GENERATED = {"version.h"}


def source_path(included):
    """Repository path of the header "flexure/<included>"."""
    if "/" not in included:
        return "include/flexure/" + included  # flexure.h and future module headers
    return included


def folder_of(path):
    return os.path.dirname(path)


def read_graph(root):
    """{file: [(included file, line number, style)]} over the library folders."""
    includes = {}
    for top in LIBRARY:
        for directory, _, names in os.walk(os.path.join(root, top)):
            for name in sorted(names):
                if not name.endswith((".h", ".cpp")):
                    continue
                path = os.path.relpath(os.path.join(directory, name), root)
                found = []
                with open(os.path.join(root, path), encoding="utf-8") as f:
                    for number, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if m and m.group(2) not in GENERATED:
                            found.append((source_path(m.group(2)), number, m.group(1)))
                includes[path] = found
    return includes


def folder_edges(includes):
    """{(from folder, to folder): [(file, line, included)]} for includes between folders."""
    edges = collections.defaultdict(list)
    for path, found in includes.items():
        for included, number, _ in found:
            a, b = folder_of(path), folder_of(included)
            if a != b:
                edges[(a, b)].append((path, number, included))
    return edges


def strongly_connected(nodes, successors):
    """Tarjan's algorithm; components with more than one node, each sorted."""
    index, low, on_stack, stack, result = {}, {}, set(), [], []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        for w in successors.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                result.append(sorted(component))

    sys.setrecursionlimit(10000)
    for v in sorted(nodes):
        if v not in index:
            visit(v)
    return sorted(result)


def print_edges(edges):
    print("folder -> folder (includes): files")
    for (a, b), uses in sorted(edges.items()):
        files = sorted({os.path.basename(p) for p, _, _ in uses})
        print(f"  {a} -> {b} ({len(uses)}): {', '.join(files)}")


def print_cycles(edges):
    successors = collections.defaultdict(set)
    nodes = set()
    for a, b in edges:
        successors[a].add(b)
        nodes.update((a, b))
    components = strongly_connected(nodes, successors)
    if not components:
        print("no cycles between folders")
        return 0
    for component in components:
        print("cycle between folders: " + ", ".join(component))
        for (a, b), uses in sorted(edges.items()):
            if a in component and b in component:
                for path, number, included in sorted(uses):
                    print(f"  {a} -> {b}: {path}:{number} includes {included}")
    return 1


def print_file_cycles(includes):
    successors = collections.defaultdict(set)
    for path, found in includes.items():
        for included, _, _ in found:
            if folder_of(included) == folder_of(path):
                successors[path].add(included)
    # A .cpp and its header are one unit: x.cpp -> y.h -> x.h is a cycle of x and y.
    def unit(path):
        return os.path.splitext(path)[0]

    unit_successors = collections.defaultdict(set)
    for a, bs in successors.items():
        for b in bs:
            if unit(a) != unit(b):
                unit_successors[unit(a)].add(unit(b))
    nodes = set(unit_successors) | {b for bs in unit_successors.values() for b in bs}
    components = strongly_connected(nodes, unit_successors)
    if not components:
        print("no cycles between files of one folder")
        return 0
    for component in components:
        print("cycle between files (.h with its .cpp): " + ", ".join(component))
    return 1


def public_closure(includes):
    seen, pending = [], ["include/flexure/flexure.h"]
    while pending:
        header = pending.pop(0)
        if header in seen:
            continue
        seen.append(header)
        pending.extend(i for i, _, _ in includes.get(header, ()) if i not in seen)
    return seen[1:]


def print_public(includes):
    closure = public_closure(includes)
    per_folder = collections.Counter(folder_of(h) for h in closure)
    print(f"<flexure/flexure.h> reaches {len(closure)} headers:")
    for folder, count in sorted(per_folder.items()):
        print(f"  {folder}: {count}")
    direct = [i for i, _, _ in includes.get("include/flexure/flexure.h", ())]
    from_benchmarks = sum(1 for h in direct if h.startswith("benchmarks/"))
    print(f"  included directly by flexure.h: {len(direct)}, of them from benchmarks/: "
          f"{from_benchmarks}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", default=ROOT, help="repository root")
    parser.add_argument("--edges", action="store_true")
    parser.add_argument("--cycles", action="store_true")
    parser.add_argument("--file-cycles", action="store_true")
    parser.add_argument("--public", action="store_true")
    args = parser.parse_args()
    if not (args.edges or args.cycles or args.file_cycles or args.public):
        args.edges = args.cycles = args.public = True
    includes = read_graph(args.root)
    edges = folder_edges(includes)
    status = 0
    if args.edges:
        print_edges(edges)
    if args.cycles:
        status |= print_cycles(edges)
    if args.file_cycles:
        status |= print_file_cycles(includes)
    if args.public:
        print_public(includes)
    return status


if __name__ == "__main__":
    sys.exit(main())

"""The generated blocks of the docs, shared by the scripts that write them (perf_tables.py,
regen_design_tables.py, make_tutorial.py): the text between `<!-- KIND: NAME -->` and
`<!-- end KIND -->` is replaced by what a function renders, and files are written whole or not at
all. Standard library only."""
import os
import re


def write_atomically(path, text):
    """Writes `text` to `path` through a temporary file and a rename: never half a file."""
    with open(path + ".tmp", "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def rewrite_blocks(path, kind, render):
    """Replaces every block `<!-- KIND: NAME -->` ... `<!-- end KIND -->` of the file `path` by
    render(NAME); a block whose render returns None is kept as it is."""
    marker = re.compile(rf"<!-- {re.escape(kind)}: (\S+) -->\n.*?<!-- end {re.escape(kind)} -->",
                        re.S)
    with open(path, encoding="utf-8") as f:
        doc = f.read()

    def replace(match):
        text = render(match.group(1))
        if text is None:
            return match.group(0)
        return f"<!-- {kind}: {match.group(1)} -->\n{text}\n<!-- end {kind} -->"

    write_atomically(path, marker.sub(replace, doc))

"""Which command wrote a file, from the file's own metadata (docs/hdf5-schema.md): the root
`schema` where the file has one (bench, models map), else the command in the root `command_line`
that every file carries (io/provenance.h), else the datasets it holds (files edited by hand or
renamed commands)."""
import shlex

from ._common import attr

# (kind, words of the command after `flexure`, a predicate on the file's datasets)
KINDS = (
    ("sweep", ("sweep", "beam"), lambda f: "alpha2" in f and "a_over_l" in f and "b_over_l" in f),
    ("path", ("path",), lambda f: "load_factor" in f and "special_points" in f),
    ("validate", ("validate",), lambda f: "rel_error" in f and "problem" in f),
    ("mechanism-analyze", ("mechanism", "analyze"),
     lambda f: "displacement" in f and "force_prbm" in f),
    ("mechanism-general", ("mechanism", "analyze"),
     lambda f: "input" in f and "input_load" in f and "models" in f),
    ("mechanism-validate", ("mechanism", "validate"),
     lambda f: "name" in f and "percent_constant_force_exact" in f and "safety_factor" in f),
    ("mechanism-tolerance", ("mechanism", "tolerance"), lambda f: "draws" in f and "parameters" in f),
    ("dynamics", ("dynamics",), lambda f: "omega" in f and "mean_force" in f),
    ("design-history", ("design", "cfm"), lambda f: "history" in f and "history/objective" in f),
    ("design-table", ("design", "cfm"), lambda f: "name" in f and "printed_objective" in f),
    ("cfm-map", ("map", "cfm"), lambda f: "Phi" in f and "Psi_raw" in f),
    ("models-map", ("models", "map"), lambda f: "reference" in f and "alpha2" in f and "n" in f),
    ("bench", ("bench",), lambda f: False),
)

DESCRIPTIONS = {
    "sweep": "flexure sweep beam: tip quantities against the load",
    "path": "flexure path: equilibrium path (load factor against the tip; under --control the "
            "support's force against the moved coordinate)",
    "validate": "flexure validate: relative error of every check",
    "mechanism-analyze": "flexure mechanism analyze: one stroke (force, PRBM error, stress)",
    "mechanism-general": "flexure mechanism analyze (general form or --model mixed): input load "
                         "against the input, equilibria and limit points",
    "mechanism-validate": "flexure mechanism validate: the table of designs",
    "mechanism-tolerance": "flexure mechanism tolerance: distributions over the sampled designs",
    "dynamics": "flexure dynamics: input force against the drive frequency",
    "design-history": "flexure design cfm: the search's convergence history",
    "design-table": "flexure design cfm --all-subclasses: the table of sub-classes",
    "cfm-map": "flexure map cfm: design-space map with contours",
    "models-map": "flexure models map: each model's error map",
    "bench": "flexure bench: error against time per method",
}


def _command_words(f):
    line = attr(f, "command_line", "")
    try:
        words = shlex.split(line)
    except ValueError:
        words = line.split()
    # Skip the program (and an mpirun launcher's words) up to the first word a command starts with.
    firsts = {k[1][0] for k in KINDS}
    for i, w in enumerate(words):
        if w.lower() in firsts:
            return [x.lower() for x in words[i:]]
    return []


def detect(f):
    """The kind of file `f` (an open h5py.File), or None."""
    schema = attr(f, "schema", "")
    if schema.startswith("flexure-bench"):
        return "bench"
    if schema.startswith("flexure-models-map"):
        return "models-map"
    words = _command_words(f)
    for kind, command, holds in KINDS:
        if tuple(words[:len(command)]) == command and (holds(f) or kind == "bench"):
            return kind
    for kind, _, holds in KINDS:
        if holds(f):
            return kind
    return None

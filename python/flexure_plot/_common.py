"""What every figure shares: errors with the tool's exit codes, units from the datasets' `units`
attributes (docs/hdf5-schema.md), the style (text >= 9 pt, legends beside the axes, never over
the data), the record of every plotted array (--dump-json) and the atomic save."""
import json
import math
import os
import tempfile

import numpy as np


from ._errors import PlotError  # noqa: F401 (re-exported)


def text(value):
    if isinstance(value, bytes):
        return value.decode()
    if isinstance(value, np.ndarray) and value.shape == ():
        return text(value[()])
    return str(value)


def attr(obj, name, default=None):
    value = obj.attrs.get(name, default)
    if isinstance(value, (bytes, np.bytes_)):
        return value.decode()
    return value


def unit(dataset, default="1"):
    return text(dataset.attrs.get("units", default))


# Shown units: lengths in mm and stresses in MPa read better than m and Pa.
DISPLAY = {"m": (1e3, "mm"), "Pa": (1e-6, "MPa")}


def display(dataset, default="1"):
    """(scale, unit shown) of a dataset: the value drawn is value * scale."""
    u = unit(dataset, default)
    return DISPLAY.get(u, (1.0, u))


def label(quantity, shown_unit):
    """`quantity [unit]`; a dimensionless quantity gets [–]."""
    u = "–" if shown_unit in ("1", "") else shown_unit
    return f"{quantity} [{u}]"


def style(plt):
    plt.rcParams.update({
        "font.size": 10,
        "axes.titlesize": 10,
        "axes.labelsize": 10,
        "xtick.labelsize": 9,
        "ytick.labelsize": 9,
        "legend.fontsize": 9,
        "figure.titlesize": 11,
        # No offset text ("1e-11+6.96e-2") beside an axis: on a nearly constant quantity it
        # overlaps the axis label and hides the value; the ticks show the numbers themselves.
        "axes.formatter.useoffset": False,
    })


def legend_beside(ax, **kwargs):
    """The legend to the right of the axes: it never covers data."""
    handles, labels = ax.get_legend_handles_labels()
    if handles:
        ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, **kwargs)


def _json_list(values):
    out = []
    for v in np.asarray(values, dtype=float).ravel():
        out.append(float(v) if math.isfinite(v) else None)
    return out


class Recorder:
    """Every array drawn, in the file's units, with the dataset it came from and the flat
    (row-major) indices taken from it, so a test can compare the figure with the file."""

    def __init__(self):
        self.series = []
        self.axes = []

    def figure(self, fig):
        """The text of every axes as drawn (call after saving: the offset texts exist only once
        the figure is drawn): labels, title and any offset text beside the ticks."""
        def entry(ax, index, parent=None):
            return {"index": index, "secondary_of": parent, "xlabel": ax.get_xlabel(),
                    "ylabel": ax.get_ylabel(),
                    "title": ax.get_title() if hasattr(ax, "get_title") else "",
                    "x_offset": ax.xaxis.get_offset_text().get_text(),
                    "y_offset": ax.yaxis.get_offset_text().get_text()}

        for k, ax in enumerate(fig.axes):
            self.axes.append(entry(ax, k))
            for child in getattr(ax, "child_axes", []):
                self.axes.append(entry(child, len(self.axes), k))

    def _source(self, source):
        if source is None:
            return None
        if isinstance(source, str):
            return {"dataset": source}
        name, indices = source
        return {"dataset": name, "indices": [int(i) for i in np.asarray(indices).ravel()]}

    def line(self, ax, x, y, *fmt, x_src=None, y_src=None, x_scale=1.0, y_scale=1.0,
             panel="", **kwargs):
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        lines = ax.plot(x * x_scale, y * y_scale, *fmt, **kwargs)
        drawn_x, drawn_y = lines[0].get_xdata(), lines[0].get_ydata()
        self.series.append({
            "panel": panel, "type": "line", "label": kwargs.get("label", ""),
            "x": _json_list(np.asarray(drawn_x, dtype=float) / x_scale),
            "y": _json_list(np.asarray(drawn_y, dtype=float) / y_scale),
            "x_source": self._source(x_src), "y_source": self._source(y_src),
        })
        return lines

    def grid(self, panel, x, y, z, x_src=None, y_src=None, z_src=None, label=""):
        """A 2-D map: z[i, j] at (x[j], y[i])."""
        self.series.append({
            "panel": panel, "type": "map", "label": label,
            "x": _json_list(x), "y": _json_list(y), "z": _json_list(z),
            "z_shape": list(np.shape(z)),
            "x_source": self._source(x_src), "y_source": self._source(y_src),
            "z_source": self._source(z_src),
        })

    def values(self, panel, v, src=None, label=""):
        """A set of values drawn as a histogram or bars."""
        self.series.append({"panel": panel, "type": "values", "label": label,
                            "y": _json_list(v), "y_source": self._source(src)})

    def dump(self, path, kind, file):
        payload = {"file": file, "kind": kind, "series": self.series, "axes": self.axes}
        write_atomically(path, lambda tmp: _write_text(tmp, json.dumps(payload)))


def _write_text(path, content):
    with open(path, "w") as f:
        f.write(content)


FORMATS = ("png", "pdf", "svg")


def check_output(path, extensions, what):
    ext = os.path.splitext(path)[1].lstrip(".").lower()
    if ext not in extensions:
        raise PlotError(f"{what} '{path}' must end in " + ", ".join("." + e for e in extensions))
    directory = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(directory):
        raise PlotError(f"{what} '{path}': the folder {directory} does not exist")
    if not os.access(directory, os.W_OK):
        raise PlotError(f"{what} '{path}': the folder {directory} is not writable")
    if os.path.isdir(path):
        raise PlotError(f"{what} '{path}' is a folder; give a file name")
    return ext


def write_atomically(path, write):
    """Writes through a temporary file in the same folder and a rename: the file appears whole or
    not at all (the rule of every file the tool writes)."""
    directory = os.path.dirname(os.path.abspath(path))
    suffix = os.path.splitext(path)[1]
    fd, tmp = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".", suffix=suffix,
                               dir=directory)
    os.close(fd)
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(tmp, 0o666 & ~umask)  # mkstemp creates 0600; give the file the usual mode
    try:
        write(tmp)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def save_figure(fig, path):
    ext = os.path.splitext(path)[1].lstrip(".").lower()
    write_atomically(path, lambda tmp: fig.savefig(tmp, dpi=120, format=ext, bbox_inches="tight"))


def finite(a):
    a = np.asarray(a, dtype=float)
    return a[np.isfinite(a)]

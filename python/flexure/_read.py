"""flexure.read: an HDF5 file written by the tool as a dict of numpy arrays with their units."""
import os

from . import _command


def read(path):
    """Reads an HDF5 file written by the tool (docs/hdf5-schema.md) into a dict.

    Every dataset becomes a numpy array under its name, every group a nested dict of the same
    form. Each dict also holds `units` (dataset name -> its `units` attribute) and `attributes`
    (the group's attributes: at the root tool_version, git_commit, command_line, ...).
    Needs h5py (Debian: python3-h5py, under /usr/bin/python3).

    Example:
      >>> flexure.sweep(alpha2="0:10:11", out="s.h5")                      # doctest: +SKIP
      >>> data = flexure.read("s.h5"); data["theta0"], data["units"]["theta0"]   # doctest: +SKIP
    """
    try:
        import h5py
    except ImportError:
        raise ImportError("flexure.read needs h5py (Debian: apt-get install python3-h5py, and "
                          "run under /usr/bin/python3)") from None
    if not os.path.exists(path):
        raise _command.InvalidInput(f"{os.fspath(path)}: no such file")
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        raise _command.InvalidInput(f"{os.fspath(path)}: not an HDF5 file ({e})") from None
    with f:
        return _group(f)


def _text(value):
    return value.decode("utf-8") if isinstance(value, bytes) else value


def _attribute(value):
    value = _text(value)
    if hasattr(value, "tolist") and getattr(value, "dtype", None) is not None and \
            value.dtype.kind in "OSU":
        return [_text(v) for v in value.tolist()]
    return value


def _group(group):
    import h5py
    out = {}
    units = {}
    for name, item in group.items():
        if name in ("units", "attributes"):
            raise _command.InvalidInput(f"{group.name}/{name}: a name flexure.read reserves")
        if isinstance(item, h5py.Group):
            out[name] = _group(item)
        else:
            data = item[()]
            if item.dtype.kind in "OS":
                data = item.asstr()[()]
            out[name] = data
            if "units" in item.attrs:
                units[name] = _text(item.attrs["units"])
    out["units"] = units
    out["attributes"] = {k: _attribute(v) for k, v in group.attrs.items()}
    return out

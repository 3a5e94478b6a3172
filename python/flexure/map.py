"""flexure.map: design-space maps (`flexure map ...`, docs/design.md "Design-space maps")."""
from . import _command


def cfm(*, config, R, d, out, K1=None, K2=None, model=None, exact_points=None, progress=None):
    """The design-space map of one configuration: `flexure map cfm`.

    config   'spp', 'lpp', 'psp', 'plp', 'ssp', 'slp', 'sps', 'lps' or 'sss'
    R, d     a value or 'START:STOP:COUNT' (d in % of r2 + r3); K1, K2 likewise where the
             configuration has those springs
    model    'prbm' (default) or 'exact' (also the exact model at every point, exact_points each)
    out      the HDF5 file of the map (required; read it with flexure.read)
    progress progress(done, total) after each block of points (up to 4096 PRBM points, 16 with
             the exact model; total: the grid's points); Ctrl-C or an exception it raises stops
             the map and no `out` file is written (docs/python.md "Progress and Ctrl-C")
    Returns the summary `flexure map cfm --json` prints (dims, ok, invalid, the best Xi').

    Example:
      >>> flexure.map.cfm(config="lpp", R="0.5:1.5:11", d=40, out="map.h5")  # doctest: +SKIP
    """
    return _command.run(["map", "cfm"], dict(config=config, R=R, d=d, K1=K1, K2=K2, model=model,
                                             exact_points=exact_points, out=out),
                        progress=progress)

"""flexure tutorial, step 1 in Python: a steel strip with a rigid link, two ways.

The same problem as step-1.cc beside it, built from the module's objects (the library's C++ types
under their C++ names, python/objects.cpp): a cross-section, a material, a flexible segment, a
rigid segment and a tip load put together as a segment chain, solved by the shooting method and by
Howell's chain algorithm; both tips and their difference are printed, and both deflected shapes
plotted with matplotlib. README.md beside it shows what it prints.

Run:  PYTHONPATH=build/python python3 examples/tutorial/step-1/step-1.py [shapes.png]
"""

# 1. Imports
#
# flexure is the compiled module; matplotlib draws with its Agg back end (no display needed).
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import flexure  # noqa: E402


def build_chain():
    """2. The problem, built from objects.

    A spring-steel strip 50 mm long, 10 mm wide and 0.5 mm thick, clamped at one end; a rigid link
    20 mm long fixed to its free end, and a 3 N force at the link's end perpendicular to the
    undeformed strip. SI units throughout (docs/units.md). Section.rectangle and Material validate
    their fields (a negative thickness raises flexure.InvalidInput naming it); flexural_rigidity
    gives E I = E b h^3/12.
    """
    strip = flexure.Section.rectangle(width=0.010, thickness=0.0005)
    steel = flexure.Material(E=200e9, nu=0.3, yield_strength=1.4e9)  # spring steel
    EI = flexure.flexural_rigidity(strip, steel)
    # Segments from the clamp to the tip; the free tip carries a dead load (fixed in direction).
    chain = flexure.SegmentChain(
        segments=[flexure.FlexibleSegment(length=0.050, EI=EI),
                  flexure.RigidSegment(length=0.020)],
        tip_load=flexure.TipLoad(Fy=3.0))
    return strip, steel, EI, chain


def solve_both(chain):
    """3. Two solutions.

    The shooting method integrates the elastica from the clamp and meets the tip's conditions by
    Newton's method (docs/theory-shooting.md); 201 shape points give the deflected shape. Howell's
    chain algorithm cuts the strip into 100 elements (Howell ch. 7, docs/theory-chain.md): a
    discretisation whose tip error falls like 1/N^3, about 0.85/N^3 of the length at
    Fy L^2/EI = 10 (docs/theory-chain.md section 3).
    """
    shot = flexure.ShootingSolver(flexure.ShootingSolver.Options(shape_points=201)).solve(chain)
    howell = flexure.ChainAlgorithmSolver(
        flexure.ChainAlgorithmSolver.Options(elements=100)).solve(chain)
    for name, result in (("shooting", shot), ("chain algorithm", howell)):
        if not result.converged():
            raise RuntimeError(f"{name}: not converged: {result.message}")
    return shot, howell


def plot(shot, howell, path):
    """5. Plotting both shapes: the shooting method's points, the chain algorithm's nodes."""
    fig, ax = plt.subplots(figsize=(6.4, 4.8), dpi=100)
    shape, nodes = shot.shape, howell.nodes
    ax.plot(shape.x * 1e3, shape.y * 1e3, "-", color="#1f77b4", lw=2,
            label=f"shooting method ({len(shape)} points)")
    ax.plot(nodes.x * 1e3, nodes.y * 1e3, "--", color="#d62728", lw=1.5,
            label=f"chain algorithm ({howell.elements} elements)")
    length = shape.s[-1] * 1e3
    ax.plot([0, length], [0, 0], color="0.6", lw=1, label="undeformed")
    ax.plot([0, 0], [-5, 5], color="black", lw=4)  # the clamp
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_aspect("equal")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper left")
    ax.set_title("Step 1: a steel strip with a rigid link, Fy = 3 N")
    # Written whole or not at all: a temporary file beside the target, then renamed.
    temporary = path + ".part.png"
    fig.savefig(temporary)
    plt.close(fig)
    os.replace(temporary, path)


def main(argv):
    png = argv[1] if len(argv) > 1 else "step-1.png"
    strip, steel, EI, chain = build_chain()
    L = chain.total_length()
    print(f"strip: L = 50 mm, b = 10 mm, h = 0.5 mm, E = 200 GPa: EI = {EI:.6g} N m^2")
    print(f"rigid link 20 mm, tip force Fy = 3 N: Fy L^2/EI = {chain.tip_load.Fy * L * L / EI:.6f}"
          " over the total length")
    shot, howell = solve_both(chain)

    # 4. Comparing the two: both tips in metres and radians, the difference in total lengths.
    for name, t, extra in (("shooting:       ", shot.tip, ""),
                           ("chain algorithm:", howell.tip, f"  ({howell.elements} elements)")):
        print(f"{name} tip x = {t.x:.12f} m  y = {t.y:.12f} m  theta = {t.theta:.12f} rad{extra}")
    dx = abs(shot.tip.x - howell.tip.x)
    dy = abs(shot.tip.y - howell.tip.y)
    dtheta = abs(shot.tip.theta - howell.tip.theta)
    print(f"difference:      |dx| = {dx:.3e} m  |dy| = {dy:.3e} m  |dtheta| = {dtheta:.3e} rad")
    print(f"largest difference in total lengths (and rad): {max(dx / L, dy / L, dtheta):.3e}")
    # The stress at the clamp from the root moment and the section modulus b h^2/6.
    stress = abs(shot.reaction.M) / strip.section_modulus()
    print(f"bending stress at the clamp: {stress / 1e6:.1f} MPa, safety factor "
          f"{steel.yield_strength / stress:.2f} against yield")

    plot(shot, howell, png)
    print(f"shapes written to {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

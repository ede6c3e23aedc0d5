"""Pictures of the THB benchmark (bench_thb.cpp's CSV files): error against degrees of freedom
for adaptive THB and uniform refinement, and the final hierarchical mesh in the parameter domain
with the points coloured by their error. Usage: thb_pictures.py OUTDIR"""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

out = sys.argv[1]
rows = list(csv.DictReader(open(out + "/thb_curves.csv")))
fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
for fit, style in (("thb", "o-"), ("uniform", "s--")):
    r = [x for x in rows if x["fit"] == fit]
    label = "THB (adaptive)" if fit == "thb" else "uniform B-spline"
    ax[0].loglog([int(x["dof"]) for x in r], [float(x["max_error"]) for x in r], style, label=label + ", max")
    ax[0].loglog([int(x["dof"]) for x in r], [float(x["mse"]) ** 0.5 for x in r], style, alpha=0.5, label=label + ", RMS")
ax[0].set_xlabel("degrees of freedom")
ax[0].set_ylabel("error / region diagonal")
ax[0].set_title("Bunny region: error against degrees of freedom")
ax[0].grid(True, which="both", alpha=0.3)
ax[0].legend(fontsize=8)
colours = ["#222222", "#1f4fd8", "#0a8a4a", "#d98a00", "#c0139a", "#990000"]
for c in csv.DictReader(open(out + "/thb_cells.csv")):
    l, u0, v0, u1, v1 = int(c["level"]), float(c["u0"]), float(c["v0"]), float(c["u1"]), float(c["v1"])
    ax[1].add_patch(Rectangle((u0, v0), u1 - u0, v1 - v0, fill=False, lw=0.6, ec=colours[min(l, 5)]))
pts = list(csv.DictReader(open(out + "/thb_points.csv")))
sc = ax[1].scatter([float(p["u"]) for p in pts], [float(p["v"]) for p in pts], c=[float(p["error"]) for p in pts], s=3, cmap="jet")
fig.colorbar(sc, ax=ax[1], label="error / diagonal")
ax[1].set_xlim(0, 1)
ax[1].set_ylim(0, 1)
ax[1].set_aspect("equal")
ax[1].set_title("Hierarchical mesh (colour: level) and point errors")
fig.tight_layout()
fig.savefig(out + "/thb_bunny.png", dpi=110)
print(out + "/thb_bunny.png")

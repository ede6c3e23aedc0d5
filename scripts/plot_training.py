#!/usr/bin/python3
"""Plots a training log (log.csv from `holefill train uvtran|bidgcn`) into one PNG: UVTran's
training losses and the validation parameter error of both stages, or BIDGCN's training loss
and validation fit MSE, against the step."""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def bidgcn(rows, png, refs):
    step = [int(r["step"]) for r in rows]
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    ax.plot(step, [float(r["loss"]) for r in rows], label="training loss (fit MSE + weighted parameter term)")
    ax.plot(step, [float(r["val_median_mse"]) for r in rows], "o-", ms=3, label="validation median fit MSE")
    for name, value, style in refs:
        ax.axhline(value, color="k", ls=style, lw=0.8, label=name)
    runs = [r.get("run") for r in rows]
    for i in range(1, len(rows)):  # a chain of fine-tuning phases (the model card's lineage log)
        if runs[i] != runs[i - 1]:
            ax.axvline((step[i - 1] + step[i]) / 2, color="grey", lw=0.6, alpha=0.6)
    ax.set_xlabel("step")
    ax.set_yscale("log")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("BIDGCN training: %d steps, %.2f h" % (step[-1], float(rows[-1]["hours"])))
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("wrote", png)


def main(log, png):
    rows = list(csv.DictReader(open(log)))
    if not rows:
        sys.exit("no rows in %s" % log)
    if "val_median_mse" in rows[0]:
        # The classical methods' medians on 1000-point clouds (docs/benchmarks.md) and the goal.
        # The paper's 6.38e-5 is a mean of PyTorch's mse_loss, a third of this measure.
        return bidgcn(rows, png, [("inverse distance 4.6e-3", 4.6e-3, ":"), ("shape-preserving 2.0e-4", 2.0e-4, "-."),
                                  ("paper's BIDGCN in this measure 1.9e-4 (mean)", 1.9e-4, (0, (1, 3))),
                                  ("issue's goal 6e-5", 6e-5, "--")])
    step = [int(r["step"]) for r in rows]
    col = lambda k: [float(r[k]) for r in rows]
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.5))
    a.plot(step, col("coarse_ce"), label="stage 1 voxel CE (dv=0.1)")
    s2 = [i for i, r in enumerate(rows) if r["stage"] == "2"]
    if s2:
        a.plot([step[i] for i in s2], [col("fine_ce")[i] for i in s2], label="stage 2 voxel CE (dv=0.01)")
    a.plot(step, [100 * k for k in col("knot_mse")], label="knot MSE x 100")
    a.set_xlabel("step")
    a.set_ylabel("training loss (mean since last point)")
    a.set_yscale("log")
    a.grid(True, which="both", alpha=0.3)
    a.legend()
    b.plot(step, col("val_param_coarse"), label="stage 1 poles")
    if s2:
        b.plot([step[i] for i in s2], [col("val_param_fine")[i] for i in s2], label="stage 2 poles")
    b.axhline(5e-3, color="k", ls="--", lw=0.8, label="goal 5e-3")
    b.set_xlabel("step")
    b.set_ylabel("validation parameter error (mean |uv - uv*|)")
    b.set_yscale("log")
    b.grid(True, which="both", alpha=0.3)
    b.legend()
    hours = float(rows[-1]["hours"])
    fig.suptitle("UVTran training: %d steps, %.2f h" % (step[-1], hours))
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("wrote", png)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else "training.png")

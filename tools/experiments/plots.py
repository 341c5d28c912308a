"""The experiments' figures, in the paper's style: grouped bars with 95 % error bars, a
histogram beside a mean ± sd bar, a scatter of success against time. PNG files, matplotlib's
Agg backend (no display needed on a cluster node)."""

from __future__ import annotations

from pathlib import Path
from typing import Mapping, Sequence

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from tools.experiments.tables import Estimate  # noqa: E402

DPI = 110


def grouped_bars(path: Path, groups: Sequence[str], series: Mapping[str, Sequence[Estimate]], *, ylabel: str,
                 title: str, percent: bool = False) -> None:
    """One cluster of bars per group (a task), one bar per series (a strategy), each with its
    interval as an error bar; ``percent`` shows rates as percentages on a 0-105 axis."""
    scale = 100 if percent else 1
    x = np.arange(len(groups))
    width = 0.8 / max(1, len(series))
    fig, ax = plt.subplots(figsize=(max(6, 1.3 * len(groups) + 2), 4.2), dpi=DPI)
    for i, (label, estimates) in enumerate(series.items()):
        values = np.nan_to_num([e.value * scale for e in estimates])
        errors = np.array([e.errors for e in estimates]).T * scale
        ax.bar(x + (i - (len(series) - 1) / 2) * width, values, width, yerr=errors, capsize=2, label=label)
    ax.set_xticks(x, groups, fontsize=8)
    ax.set_ylabel(ylabel)
    if percent:
        ax.set_ylim(0, 105)
    _finish(fig, ax, path, title, legend=len(series) > 1)


def success_vs_time(path: Path, points: Mapping[str, tuple[Estimate, Estimate]], *, title: str) -> None:
    """One point per strategy: mean wall time per episode (x) against success (y), both with their
    intervals."""
    fig, ax = plt.subplots(figsize=(6, 4.2), dpi=DPI)
    for label, (seconds, success) in points.items():
        ax.errorbar([seconds.value], [100 * success.value], xerr=np.array([seconds.errors]).T,
                    yerr=100 * np.array([success.errors]).T, fmt="o", capsize=3, label=label)
    ax.set_xlabel("wall time per episode, s")
    ax.set_ylabel("success (world's truth), %")
    _finish(fig, ax, path, title, legend=True)


def histogram_and_mean(path: Path, samples: Mapping[str, Sequence[float]], *, xlabel: str, title: str) -> None:
    """Left, the distribution of each sample (integer bins); right, each sample's mean ± sd."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4), dpi=DPI, gridspec_kw={"width_ratios": [2, 1]})
    top = max((max(s) for s in samples.values() if len(s)), default=0)
    bins = np.arange(-0.5, top + 1.5)
    left.hist([list(s) for s in samples.values()], bins=bins, label=list(samples), density=True)
    left.set_xlabel(xlabel)
    left.set_ylabel("share of uncertain checks")
    left.legend(fontsize=8)
    names = list(samples)
    means = [float(np.mean(samples[n])) if len(samples[n]) else 0.0 for n in names]
    sds = [float(np.std(samples[n], ddof=1)) if len(samples[n]) > 1 else 0.0 for n in names]
    right.bar(names, means, yerr=sds, capsize=4, color=[f"C{i}" for i in range(len(names))])
    right.set_ylabel(f"mean ± sd, {xlabel}")
    _finish(fig, right, path, title, legend=False)


def _finish(fig, ax, path: Path, title: str, legend: bool) -> None:
    ax.grid(axis="y", alpha=0.3)
    if legend:  # below the axes, where it hides no bar
        ax.legend(fontsize=8, frameon=False, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=4)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)

"""The paper report's figures (analysis/figures/*.png): paper against simulation per table, the
scatter of every cell, the per-node timeline."""
# numpy (0.1 s of CPU a start) is imported by the functions that use it: a refusal needs none.

from .cells import read_json, table_scenes, unique_cells
from .text import seconds

matplotlib = plt = None   # loaded by _load() on the first figure


def _load():
    """matplotlib on the first figure drawn, not on import: report.py refusing its inputs does
    not pay its second of start-up."""
    global matplotlib, plt
    if plt is None:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.patches  # noqa: F401
        import matplotlib.pyplot
        import matplotlib.ticker  # noqa: F401
        plt = matplotlib.pyplot


FIGURES = None   # set by analysis/report.py: the folder the figures go to

SCENE_COLOURS = {"scene0": "tab:purple", "scene1": "tab:blue", "scene2": "tab:orange",
                 "scene3": "tab:green"}


def save(fig, name):
    _load()
    FIGURES.mkdir(parents=True, exist_ok=True)
    # No "Software"/date metadata: the same inputs give the same bytes.
    fig.savefig(FIGURES / name, dpi=110, bbox_inches="tight", metadata={"Software": None})
    plt.close(fig)
    return f"figures/{name}"


def plot_paper_and_sim(ax, cells, x_of):
    """One colour per scene: paper dashed with open markers, simulation solid with filled ones;
    out-of-memory cells as an x on the axis floor."""
    for scene in sorted({c.scene for c in cells}):
        mine = [c for c in cells if c.scene == scene]
        colour = SCENE_COLOURS[scene]
        paper = [(x_of(c), c.paper) for c in mine if c.paper is not None]
        sim = [(x_of(c), c.sim) for c in mine if c.sim is not None]
        if paper:
            ax.plot(*zip(*paper), "--o", color=colour, mfc="white", label=f"{scene} paper")
        if sim:
            ax.plot(*zip(*sim), "-s", color=colour, label=f"{scene} simulation")
        for c in mine:
            if c.status == "out_of_memory":
                ax.plot(x_of(c), 0, "x", color=colour, ms=10, mew=2, clip_on=False,
                        transform=ax.get_xaxis_transform(), label=f"{scene} sim out of memory")
    ax.set_yscale("log")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)


def figure_time_vs_R(inputs):
    _load()
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    for ax, number, V in ((axes[0], 1, 0), (axes[1], 2, 3)):
        cells = [c for c in inputs.cells if c.table == number]
        plot_paper_and_sim(ax, cells, lambda c: c.R)
        ax.set_xscale("log", base=2)
        Rs = sorted({c.R for c in cells})
        ax.set_xticks(Rs, [str(R) for R in Rs])
        ax.set_xlabel("R, radiosity processors")
        ax.set_ylabel("seconds per iteration")
        ax.set_title(f"Table {number}: V = {V} visibility processors each")
    return save(fig, "time_vs_R.png")


def figure_time_vs_V(inputs):
    _load()
    fig, ax = plt.subplots(figsize=(7, 4.8))
    cells = [c for c in inputs.cells if c.table == 3]
    # V+1 on a log2 axis: the nodes per group double from column to column (V=0 fits).
    plot_paper_and_sim(ax, cells, lambda c: c.V + 1)
    ax.set_xscale("log", base=2)
    Vs = sorted({c.V for c in cells})
    ax.set_xticks([V + 1 for V in Vs], [str(V) for V in Vs])
    ax.set_xlabel("V, visibility processors per radiosity processor (R = 4)")
    ax.set_ylabel("seconds per iteration")
    ax.set_title("Table 3: R = 4, varying V")
    return save(fig, "time_vs_V.png")


def bars(ax, cells, labels):
    """Paper (hatched) and simulation (solid) side by side per configuration."""
    import numpy as np
    x = np.arange(len(cells))
    width = 0.38
    colour = SCENE_COLOURS[cells[0].scene]
    paper = [c.paper if c.paper is not None else 0 for c in cells]
    sim = [c.sim if c.sim is not None else 0 for c in cells]
    ax.bar(x - width / 2, paper, width, color="white", edgecolor=colour, hatch="//",
           label="paper")
    ax.bar(x + width / 2, sim, width, color=colour, label="simulation")
    for i, c in enumerate(cells):
        if c.sim is None:
            ax.text(x[i] + width / 2, 0.02, "out of memory" if c.status == "out_of_memory"
                    else c.status, rotation=90, ha="center", va="bottom", fontsize=8,
                    transform=ax.get_xaxis_transform())
    ax.set_xticks(x, labels, fontsize=8)
    ax.grid(True, axis="y", which="both", alpha=0.3)
    ax.legend(fontsize=8)


def config_label(c):
    label = f"R={c.R}\nV={c.V}"
    if (c.sim_R, c.sim_V) != (c.R, c.V):
        label += f"\n(run as\n{c.sim_R}/{c.sim_V})"
    return label


def figure_table4(inputs):
    _load()
    scenes = table_scenes(inputs.paper["tables"][3])
    fig, axes = plt.subplots(1, len(scenes), figsize=(5 * len(scenes), 4.8))
    for ax, scene in zip(axes, scenes):
        cells = [c for c in inputs.cells if c.table == 4 and c.scene == scene]
        bars(ax, cells, [config_label(c) for c in cells])
        ax.set_title(f"Table 4, {scene} (64 nodes)")
        ax.set_ylabel("seconds per iteration")
    return save(fig, "table4_64_nodes.png")


def figure_table5(inputs):
    import numpy as np
    _load()
    fig, ax = plt.subplots(figsize=(9, 4.8))
    cells = [c for c in inputs.cells if c.table == 5]
    bars(ax, cells, [f"R={c.R}\nV={c.V}\nT={c.T}" for c in cells])
    # Log scale: one node takes 10-20x the others. Bars need a fixed floor (a decade below the
    # smallest value) and plain 1-2-5 tick labels, or the autoscaled floor hides their ratios.
    ax.set_yscale("log")
    values = [v for c in cells for v in (c.paper, c.sim) if v]
    ax.set_ylim(10 ** np.floor(np.log10(min(values))), max(values) * 1.5)
    ax.yaxis.set_major_locator(matplotlib.ticker.LogLocator(subs=(1, 2, 5)))
    ax.yaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_ylabel("total seconds to convergence")
    ax.set_title("Table 5: scene0 to convergence")
    return save(fig, "table5_scene0.png")


def figure_scatter(inputs):
    import numpy as np
    _load()
    cells = [c for c in unique_cells(inputs.cells) if c.error is not None]
    fig, ax = plt.subplots(figsize=(6, 6))
    for scene in sorted({c.scene for c in cells}):
        for calibration, marker in ((False, "o"), (True, "*")):
            mine = [c for c in cells if c.scene == scene and c.calibration == calibration]
            if mine:
                ax.scatter([c.paper for c in mine], [c.sim for c in mine], marker=marker,
                           s=60 if calibration else 30, color=SCENE_COLOURS[scene],
                           label=f"{scene}{' (calibration)' if calibration else ''}")
    if cells:
        values = [c.paper for c in cells] + [c.sim for c in cells]
        line = np.array([min(values) / 1.5, max(values) * 1.5])
        ax.plot(line, line, "k-", lw=1, label="simulation = paper")
        ax.plot(line, line * 2, "k:", lw=1, label="factor 2")
        ax.plot(line, line / 2, "k:", lw=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("paper (seconds)")
    ax.set_ylabel("simulation (seconds)")
    ax.set_title("Every cell, Tables 1-5")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    return save(fig, "scatter.png")


GANTT_COLOURS = {"compute": "tab:green", "overhead": "tab:red", "wait": "lightgrey"}


def figure_gantt(inputs):
    _load()
    cell = inputs.timeline
    trace_path = inputs.results_dir / cell.trace_file if cell.trace_file else None
    if cell.result is None or trace_path is None or not trace_path.exists():
        return None
    slices = {}
    for event in read_json(trace_path)["traceEvents"]:
        if event["ph"] == "X":
            # By category (compute, overhead, wait): a send or receive is named by its
            # message's kind (docs/result-format.md, "The trace").
            slices.setdefault((event["tid"], event["cat"]), []).append(
                (event["ts"] / 1e6, event["dur"] / 1e6))
    nodes = cell.result["nodes"]
    fig, ax = plt.subplots(figsize=(12, 0.2 * len(nodes) + 1.5))
    for row, node in enumerate(nodes):
        for what, colour in GANTT_COLOURS.items():
            ax.broken_barh(slices.get((node["node"], what), []), (row - 0.4, 0.8),
                           facecolors=colour, edgecolors="none")
    ax.set_yticks(range(len(nodes)),
                  [f"{n['node']} rad {n['rank']}" if n["role"] == "radiosity"
                   else f"{n['node']} vis of {n['rank']}" for n in nodes], fontsize=6)
    for tick, node in zip(ax.get_yticklabels(), nodes):
        tick.set_fontweight("bold" if node["role"] == "radiosity" else "normal")
    ax.invert_yaxis()
    ax.set_ylim(len(nodes) - 0.5, -0.5)
    ax.set_xlim(0, cell.result["simulated_seconds"])
    ax.set_xlabel("simulated seconds")
    ax.set_ylabel("node (radiosity processor rank / visibility processor of radiosity rank)")
    ax.set_title(f"{cell.scene}, R={cell.R}, V={cell.V}: first iteration per node")
    ax.legend(handles=[matplotlib.patches.Patch(color=c, label=w)
                       for w, c in GANTT_COLOURS.items()],
              loc="upper center", bbox_to_anchor=(0.5, -0.06 * 64 / len(nodes)), ncol=3)
    return save(fig, "gantt_scene2_R8_V7.png")


def gantt_summary(cell):
    """Totals of the traced iteration per role, so the figure's thin slices can be read."""
    import numpy as np
    lines = []
    for role in ("radiosity", "visibility"):
        mine = [n for n in cell.result["nodes"] if n["role"] == role]
        if mine:
            mean = {k: np.mean([n[f"{k}_seconds"] for n in mine])
                    for k in ("compute", "overhead", "waiting")}
            lines.append(f"{len(mine)} {role} processors, mean per node: "
                         f"{seconds(mean['compute'])} s compute, "
                         f"{seconds(mean['overhead'])} s overhead, "
                         f"{seconds(mean['waiting'])} s waiting.")
    return lines


def figures_section(inputs):
    out = ["## Figures", "",
           "Paper dashed with open markers, simulation solid with filled markers; one colour "
           "per scene.", "",
           f"![time vs R, Tables 1 and 2]({figure_time_vs_R(inputs)})", "",
           f"![time vs V, Table 3]({figure_time_vs_V(inputs)})", "",
           f"![64-node configurations, Table 4]({figure_table4(inputs)})", "",
           f"![scene0 to convergence, Table 5]({figure_table5(inputs)})", ""]
    gantt = figure_gantt(inputs)
    if gantt:
        cell = inputs.timeline
        out += [f"Timeline of the traced run (`experiments/timeline.json`: {cell.label}, "
                f"{cell.result['iterations']} iteration, "
                f"{seconds(cell.result['simulated_seconds'])} simulated seconds):", ""]
        out += [f"- {line}" for line in gantt_summary(cell)]
        out += ["", f"![per-node timeline]({gantt})", ""]
    else:
        out += ["Timeline: the traced run (`experiments/timeline.json`) has no result yet.", ""]
    return out

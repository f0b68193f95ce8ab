"""The analysis side of the simulator in one package (docs/sweeps.md, "The Python package").

Import it from analysis/ scripts directly, from elsewhere after putting <repository>/analysis on
sys.path (experiments/sweep, tests/ and the Snakefile do).

    ncube.paths     where the repository, ./simulate, scenes/ and platforms/ are
    ncube.options   every ./simulate option a sweep may set: flag, default, result-file field
    ncube.simulate  running ./simulate for one configuration
    ncube.results   reading result files, "seconds per iteration", whether a result is done
    ncube.sweep     sweep files: loading, strict validation, cells and their identity
    ncube.run_cell  the job that computes one cell (what Snakemake runs)
    ncube.runner    running sweeps through Snakemake (local cores, Slurm, any cluster)
    ncube.summary   a sweep's CSV table and plots
    ncube.findings  the one definition of each of the paper's findings F1-F6
    ncube.headline  the paper's headline (visibility processors against the naive V = 0), decided
    ncube.opening   every results page's opening: what it found, from the page's own tables
    ncube.paper     the paper report (analysis/report.py)
    ncube.interpreter  which Python runs a script (Debian's /usr/bin/python3, restarted into)
    ncube.page      a page script's refusal without results, or its word that it runs its cells
"""

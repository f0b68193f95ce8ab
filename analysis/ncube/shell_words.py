"""Words for the only command lines the sweep tool hands to a shell: Snakemake's rules
(experiments/Snakefile, which quote with Snakemake's own ":q") and the cluster submit and status
commands (ncube.runner), which Snakemake first fills in as a format string and then gives to a
shell. A value from data (the results folder's path, the repository's path) goes in through
template_word and nowhere else, so that no path, name or setting can become shell syntax
(docs/sweeps.md, "What runs")."""
import shlex


def template_word(value):
    """One shell word holding exactly str(value), safe inside a Snakemake format string: quoted
    for the shell (shlex.quote), and its braces doubled so that Snakemake's formatting gives
    them back unchanged instead of reading them as fields."""
    return shlex.quote(str(value)).replace("{", "{{").replace("}", "}}")

#!/usr/bin/python3
"""The prediction's spread: docs/machines/prediction_table.py run K times (default 5).

    /usr/bin/python3 bench/prediction_spread.py [--runs K] [--repeats N] [--time-cap S] [--no-page]

Each run is a whole prediction, a fresh build/machine_probe and then the table; each is
appended as one record to docs/machines/prediction_records.jsonl (and printed as a `record:`
line, so that a machine whose files are thrown away, CI's, can be copied into it), and the
page's tables are made again from all the records: every row's median, least and worst miss
over the runs, per machine and over machines, the bound held against the worst run. A missed
bound is a finding, not a failure: the exit is 0 unless a run fails.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "docs", "machines"))
import prediction_table  # noqa: E402

if __name__ == "__main__":
    sys.exit(prediction_table.main(default_runs=5))

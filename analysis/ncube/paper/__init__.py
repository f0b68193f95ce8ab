"""The paper report: analysis/report.py puts these modules together."""

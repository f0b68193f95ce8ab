#!/usr/bin/python3
"""Prints, as JSON, the options a Python program defines with argparse, without running it:
the program runs as __main__ until it parses its arguments, where it stops (exit 0) and prints
each option's flags (none for a positional), dest, type's name, nargs, metavar, choices,
default and help. A program that parses no arguments prints
null. usage: argparse_options.py PROGRAM"""
import argparse
import json
import runpy
import sys


class Parsed(Exception):
    pass


def describe(parser, *_args, **_kwargs):
    options = []
    for action in parser._actions:   # argparse keeps no public list of its options
        if isinstance(action, (argparse._HelpAction, argparse._VersionAction,
                               argparse._SubParsersAction)):
            continue
        kind = getattr(action.type, "__name__", None) if action.type else None
        default = action.default
        if not isinstance(default, (str, int, float, bool, type(None))):
            default = str(default)
        options.append({"flags": action.option_strings, "dest": action.dest, "type": kind,
                        "nargs": action.nargs, "takes_value": action.nargs != 0,
                        "positional": not action.option_strings,
                        "metavar": action.metavar if isinstance(action.metavar, str) else None,
                        "choices": [str(c) for c in action.choices] if action.choices else None,
                        "default": default, "help": action.help or ""})
    print(json.dumps(options))
    raise Parsed


def install():
    """Makes every parser print its options and stop (Parsed) instead of parsing."""
    argparse.ArgumentParser.parse_args = describe
    argparse.ArgumentParser.parse_known_args = describe


if __name__ == "__main__":
    install()
    program = sys.argv[1]
    sys.argv = [program]
    sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(program)))
    try:
        runpy.run_path(program, run_name="__main__")
    except Parsed:
        sys.exit(0)
    except SystemExit:
        pass
    print("null")

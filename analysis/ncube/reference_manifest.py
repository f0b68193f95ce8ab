#!/usr/bin/python3
"""The committed accuracy references' identity (docs/accuracy.md, "Which scenes"), cheap to
check: analysis/reference/manifest/<scene>.json records, per reference, the command that made it,
the SHA-256 of its content (the file but for host_seconds and code_version, as
tests/reference_solution_test.sh compares files), its scene file's SHA-256, the command's wall
seconds and peak host memory; and a fingerprint: a small run (FINGERPRINT below) and the
SHA-256 of its content, made by the same build (manifest/fingerprint.json; each record written
whole, never read and rewritten: the output rule). Regenerating a reference costs minutes (scene1
about an hour); the fingerprint, seconds: when this build's fingerprint is the recorded one,
the program computes what it computed when the references were made, so they need not be run
again to be trusted; when it differs, the references are stale (regenerate them with
experiments/claims/references).

usage: reference_manifest.py run DIR --build BUILD --samples K --refine N [--part-size L] SCENE
           (runs BUILD/reference_solution SCENE ... --out DIR/SCENE.json, records it)
       reference_manifest.py record DIR SCENE   (records DIR/SCENE.json made by its command
           outside this tool: its seconds are the file's host_seconds, its memory not measured)
       reference_manifest.py fingerprint DIR --build BUILD   (records the fingerprint)
       reference_manifest.py check DIR --build BUILD [--scenes-dir SCENES]
           (exit 0 when every reference in DIR is recorded, unchanged, of today's scene file
           and made by the recorded command, and the fingerprint reproduces; else 1, one line
           per problem)
Exit codes: 0; 1 a check failed; 2 bad input; 4 the reference program failed; 5 the manifest
could not be written."""
import argparse
import hashlib
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from ncube import input_file, output_file  # noqa: E402

MANIFEST = "manifest"   # the folder of records beside the references
REFERENCE_BYTES = 64 << 20
# Small enough for seconds, large enough to pass every branch the references take: near and
# far pairs, blockers, the open share (the blocks stand on the floor), parts (--refine 2)
# averaged into elements, the solver and the self-agreement.
FINGERPRINT = ["cornell-box", "--samples", "4", "--refine", "2"]
VOLATILE = ("host_seconds", "code_version")


def content_sha256(path):
    """The SHA-256 of a reference file's content but for its host-time and version fields."""
    data = input_file.read_json(path, "reference file", REFERENCE_BYTES)
    for key in VOLATILE:
        data.pop(key, None)
    return hashlib.sha256(json.dumps(data, sort_keys=True, separators=(",", ":")).encode()).hexdigest()


def command_of(scene, samples, refine, part_size=None):
    return (f"build/reference_solution {scene} --samples {samples} --refine {refine}"
            + (f" --part-size {part_size:g}" if part_size else ""))


def read_manifest(folder):
    records = Path(folder) / MANIFEST
    manifest = {"references": {}, "fingerprint": None}
    if records.is_dir():
        for path in sorted(records.glob("*.json")):
            entry = input_file.read_json(path, "reference manifest record", 1 << 20)
            if path.stem == "fingerprint":
                manifest["fingerprint"] = entry
            else:
                manifest["references"][path.stem] = entry
    return manifest


def write_record(folder, name, entry):
    records = Path(folder) / MANIFEST
    records.mkdir(parents=True, exist_ok=True)
    output_file.write(records / f"{name}.json", json.dumps(entry, indent=1, sort_keys=True) + "\n")


class ProgramFailed(Exception):
    pass


def run_program(build, arguments):
    """Runs BUILD/reference_solution with ARGUMENTS: (wall seconds, peak resident bytes). The
    peak is the largest child's this process waited for (getrusage): each `run` is its own
    process, so it is the reference's."""
    start = time.time()
    done = subprocess.run([str(Path(build) / "reference_solution")] + arguments + ["--quiet"])
    seconds = time.time() - start
    if done.returncode != 0:
        raise ProgramFailed(f"reference_solution {' '.join(arguments)}: exit {done.returncode}")
    return seconds, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024


def fingerprint_sha256(build):
    """The fingerprint run's content SHA-256. With NCUBE_FINGERPRINT_CACHE=DIR (the tests, which
    check several folders against one build) it is kept in DIR under the SHA-256 of the program
    file and the command, and read from there by the next check of the same program: the same
    file gives the same run. Without it, every call runs."""
    cache = os.environ.get("NCUBE_FINGERPRINT_CACHE")
    kept = None
    if cache:
        program = Path(build) / "reference_solution"
        key = hashlib.sha256(program.read_bytes() + json.dumps(FINGERPRINT).encode()).hexdigest()
        kept = Path(cache) / f"{key}.txt"
        if kept.is_file():   # through the input gate like every file read (a cache, too)
            cached = input_file.read_input_text(kept, "fingerprint cache", 1 << 10).strip()
            if re.fullmatch(r"[0-9a-f]{64}", cached):
                return cached   # anything else is not a cached SHA-256: run again
    with tempfile.TemporaryDirectory(prefix="reference-fingerprint-") as scratch:
        out = Path(scratch) / "fingerprint.json"
        run_program(build, FINGERPRINT + ["--threads", "0", "--out", str(out)])
        sha = content_sha256(out)
    if kept is not None:   # the output rule writes whole files: two checks at once are safe
        kept.parent.mkdir(parents=True, exist_ok=True)
        output_file.write(kept, sha + "\n")
    return sha


def scene_sha256(scenes_dir, name):
    data = input_file.read_input_bytes(Path(scenes_dir) / f"{name}.json", "scene file",
                                       input_file.SCENE_FILE_BYTES)
    return "sha256:" + hashlib.sha256(data).hexdigest()


def run(args):
    folder = Path(args.dir)
    out = folder / f"{args.scene}.json"
    seconds, peak = run_program(args.build, [args.scene, "--samples", str(args.samples),
                                             "--refine", str(args.refine), "--out", str(out)]
                                + (["--part-size", f"{args.part_size:g}"] if args.part_size else []))
    reference = input_file.read_json(out, "reference file", REFERENCE_BYTES)
    write_record(folder, args.scene, {
        "command": command_of(args.scene, args.samples, args.refine, args.part_size),
        "content_sha256": content_sha256(out),
        "scene_sha256": reference["scene_sha256"],
        "wall_seconds": round(seconds, 1),
        "peak_memory_bytes": peak,
        "code_version": reference.get("code_version", ""),
    })
    print(f"reference_manifest: {args.scene}: {seconds:.0f} s, peak memory {peak / 1e9:.2f} GB")
    return 0


def record(args):
    folder = Path(args.dir)
    out = folder / f"{args.scene}.json"
    reference = input_file.read_json(out, "reference file", REFERENCE_BYTES)
    write_record(folder, args.scene, {
        "command": command_of(args.scene, reference["samples"], reference["refine"],
                              reference.get("part_size")),
        "content_sha256": content_sha256(out),
        "scene_sha256": reference["scene_sha256"],
        "wall_seconds": round(reference["host_seconds"], 1),
        "peak_memory_bytes": None,
        "code_version": reference.get("code_version", ""),
    })
    return 0


def fingerprint(args):
    write_record(args.dir, "fingerprint",
                 {"command": "build/reference_solution " + " ".join(FINGERPRINT),
                  "content_sha256": fingerprint_sha256(args.build)})
    return 0


def check(args):
    folder = Path(args.dir)
    manifest = read_manifest(folder)
    problems = []
    listed = manifest["references"]
    for path in sorted(folder.glob("*.json")):
        if path.stem not in listed:
            problems.append(f"{path.name}: no record in {MANIFEST}/ (made by experiments/claims/references?)")
    for scene, entry in sorted(listed.items()):
        path = folder / f"{scene}.json"
        if not path.exists():
            problems.append(f"{scene}: recorded in {MANIFEST}/ but {path.name} is missing")
            continue
        reference = input_file.read_json(path, "reference file", REFERENCE_BYTES)
        if content_sha256(path) != entry["content_sha256"]:
            problems.append(f"{path.name}: its content is not what its command made (edited?)")
        if command_of(scene, reference["samples"], reference["refine"],
                      reference.get("part_size")) != entry["command"]:
            problems.append(f"{path.name}: samples {reference['samples']}, refine "
                            f"{reference['refine']}: not its recorded command {entry['command']}")
        today = scene_sha256(args.scenes_dir, scene)
        if reference["scene_sha256"] != today or entry["scene_sha256"] != today:
            problems.append(f"{path.name}: of another version of scenes/{scene}.json: regenerate it")
    recorded = manifest.get("fingerprint")
    if not recorded:
        problems.append(f"{MANIFEST}/: no fingerprint recorded")
    elif fingerprint_sha256(args.build) != recorded["content_sha256"]:
        problems.append("the fingerprint (" + recorded["command"] + ") differs from the one recorded "
                        "with the references: the program computes otherwise now; regenerate them "
                        "(experiments/claims/references) or find what changed")
    for problem in problems:
        print("reference_manifest:", problem)
    return 1 if problems else 0


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)
    one = commands.add_parser("run")
    one.add_argument("dir")
    one.add_argument("scene")
    one.add_argument("--build", required=True)
    one.add_argument("--samples", type=int, required=True)
    one.add_argument("--refine", type=int, required=True)
    one.add_argument("--part-size", type=float, default=0.0)
    kept = commands.add_parser("record")
    kept.add_argument("dir")
    kept.add_argument("scene")
    mark = commands.add_parser("fingerprint")
    mark.add_argument("dir")
    mark.add_argument("--build", required=True)
    test = commands.add_parser("check")
    test.add_argument("dir")
    test.add_argument("--build", required=True)
    test.add_argument("--scenes-dir", default=str(Path(__file__).resolve().parents[2] / "scenes"))
    args = parser.parse_args(argv)
    try:
        return {"run": run, "record": record, "fingerprint": fingerprint,
                "check": check}[args.command](args)
    except input_file.InputFileError as e:
        print(f"reference_manifest: {e}", file=sys.stderr)
        return 2
    except ProgramFailed as e:
        print(f"reference_manifest: {e}", file=sys.stderr)
        return 4
    except (KeyError, TypeError) as e:
        print(f"reference_manifest: {MANIFEST}: not a manifest ({e})", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"reference_manifest: cannot write the manifest: {e}", file=sys.stderr)
        return 5


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""A PrairieLearn-style external grader that needs no network: it checks a
submission with the offline `mechdyn check` and writes results.json.

    python3 pl_grader.py [--root /grade] [--mechdyn mechdyn]

PrairieLearn mounts the job at /grade: the question's data in
/grade/data/data.json (`params` with `template` and `variant` or
`parameters`, `required`: the pointers the score counts, so an answer left
out scores 0, optional `tolerance`), the student's files in /grade/student/
(answers.json: {"POINTER": value or "VALUE UNIT"}), and reads
/grade/results/results.json, which this writes: `gradable`, `score`,
`message`, `tests` (one per answer). A submission that cannot be read is
written as not gradable, with the reason.
"""

import argparse
import json
import os
import subprocess
import sys


def results(root, mechdyn):
    with open(os.path.join(root, "data", "data.json"), encoding="utf-8") as f:
        params = json.load(f).get("params", {})
    try:
        with open(os.path.join(root, "student", "answers.json"), encoding="utf-8") as f:
            answers = json.load(f)
        if not isinstance(answers, dict) or not answers:
            raise ValueError("answers.json must be an object of answers by pointer")
    except (OSError, ValueError) as e:
        return {"gradable": False, "score": 0.0, "message": f"The submission could not be read: {e}",
                "format_errors": [str(e)]}
    check = {"template": params["template"], "answers": answers, "format": "prairielearn"}
    for field in ("variant", "parameters", "required", "tolerance", "tolerances", "reveal"):
        if field in params:
            check[field] = params[field]
    run = subprocess.run([mechdyn, "check", "-"], input=json.dumps(check), capture_output=True, text=True)
    if run.returncode != 0:
        problem = run.stderr.strip()
        return {"gradable": False, "score": 0.0, "message": f"The check was refused: {problem}",
                "format_errors": [problem]}
    return json.loads(run.stdout)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--root", default="/grade")
    p.add_argument("--mechdyn", default="mechdyn")
    a = p.parse_args()
    doc = results(a.root, a.mechdyn)
    os.makedirs(os.path.join(a.root, "results"), exist_ok=True)
    with open(os.path.join(a.root, "results", "results.json"), "w", encoding="utf-8") as f:
        json.dump(doc, f, indent=1)
    print(f"score {doc.get('score')}, gradable {doc.get('gradable')}", file=sys.stderr)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""A PrairieLearn-style external grader that asks a mechdyn service.

    python3 pl_client_grader.py --service http://mechdyn:8080 [--root /grade]

PrairieLearn mounts the job at /grade: the question's data in
/grade/data/data.json (`params` with `template` and `variant` or
`parameters`, `required`: the pointers the score counts, optional
`tolerance`), the student's answers in /grade/student/answers.json
({"POINTER": value or "VALUE UNIT"}), and reads /grade/results/results.json,
which this writes. A submission or a check the service refuses is written
as not gradable, with the service's reason (each field's pointer and
message). `pl_grader.py` does the same offline, with the binary.
"""

import argparse
import json
import os
import sys
from typing import Any

from mechdyn_client import Mechdyn, MechdynError
from mechdyn_client.generated.models import PrairieLearn


def not_gradable(message: str) -> dict[str, Any]:
    return {"gradable": False, "score": 0.0, "message": message, "format_errors": [message]}


def results(root: str, service: Mechdyn) -> dict[str, Any]:
    with open(os.path.join(root, "data", "data.json"), encoding="utf-8") as f:
        params = json.load(f).get("params", {})
    try:
        with open(os.path.join(root, "student", "answers.json"), encoding="utf-8") as f:
            answers = json.load(f)
        if not isinstance(answers, dict) or not answers:
            raise ValueError("answers.json must be an object of answers by pointer")
    except (OSError, ValueError) as e:
        return not_gradable(f"The submission could not be read: {e}")
    check: dict[str, Any] = {"template": params["template"], "answers": answers, "format": "prairielearn"}
    for field in ("variant", "parameters", "required", "tolerance", "tolerances", "reveal"):
        if field in params:
            check[field] = params[field]
    try:
        result = service.check(check).result
    except MechdynError as e:
        return not_gradable(f"The check was refused: {e}")
    assert isinstance(result, PrairieLearn)
    return result.to_dict()


def main() -> None:
    p = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    p.add_argument("--root", default="/grade")
    p.add_argument("--service", default="http://127.0.0.1:8080")
    a = p.parse_args()
    with Mechdyn(a.service) as service:
        doc = results(a.root, service)
    os.makedirs(os.path.join(a.root, "results"), exist_ok=True)
    with open(os.path.join(a.root, "results", "results.json"), "w", encoding="utf-8") as f:
        json.dump(doc, f, indent=1)
    print(f"score {doc.get('score')}, gradable {doc.get('gradable')}", file=sys.stderr)


if __name__ == "__main__":
    main()

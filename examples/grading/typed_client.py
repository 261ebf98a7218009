#!/usr/bin/env python3
"""Check one student's answers with a client generated from the service's own document.

    openapi-python-client generate --url http://127.0.0.1:8080/openapi.json \\
        --config openapi/openapi-python-client.yaml --meta none --output-path mechdyn_client
    python3 typed_client.py http://127.0.0.1:8080 s001 "260 slug*ft^2" 353.5

The answers are P.103's exact and approximate flywheel inertias (the
template `p103-slider-flywheel`), each a number in SI or "VALUE UNIT". It
prints the score and each answer's feedback, then reads the stored check back
from `GET /v1/jobs/{id}`, typed as a check job, and lists the student's
checks by their label.
"""

import sys

from mechdyn_client import Client
from mechdyn_client.api.grading import create_check
from mechdyn_client.api.jobs import get_job, list_jobs
from mechdyn_client.models import CheckRequest, JobCheck


def main(base, student, exact, approximate):
    client = Client(base_url=base, raise_on_unexpected_status=True)
    request = CheckRequest.from_dict({
        "template": "p103-slider-flywheel",
        "answers": {"inertia_exact": exact, "inertia_approximate": approximate},
    })
    check = create_check.sync(client=client, body=request, label=student)
    print(f"{student}: score {check.result.score} ({check.result.passed} of {check.result.total})")
    for item in check.result.items:
        print(f"  {item.pointer}: {'pass' if item.pass_ else 'fail'}: {item.feedback}")
    stored = get_job.sync(id=check.id, client=client)
    assert isinstance(stored, JobCheck) and stored.result.score == check.result.score
    mine = list_jobs.sync(client=client, label=student)
    print(f"  stored as job {stored.id}; {len(mine.items)} check(s) labelled {student}")


if __name__ == "__main__":
    main(*sys.argv[1:5])

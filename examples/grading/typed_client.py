#!/usr/bin/env python3
"""Check one student's answers with mechdyn's Python client (clients/python).

    pip install ./clients/python
    python3 typed_client.py http://127.0.0.1:8080 s001 "260 slug*ft^2" 353.5

The answers are P.103's exact and approximate flywheel inertias (the
template `p103-slider-flywheel`), each a number in SI or "VALUE UNIT". It
prints the score and each answer's feedback, reads the stored check back
typed, and the reference value the answers were checked against.
"""

import sys

from mechdyn_client import Mechdyn, MechdynError
from mechdyn_client.generated.models import CheckResult, JobOfCheckOutput


def main(base: str, student: str, exact: str, approximate: str) -> int:
    with Mechdyn(base) as service:
        try:
            check = service.check(
                {
                    "template": "p103-slider-flywheel",
                    "answers": {"inertia_exact": exact, "inertia_approximate": approximate},
                },
                label=student,
            )
        except MechdynError as e:
            print(f"{student}: not graded: {e}", file=sys.stderr)
            return 1
        result = check.result
        assert isinstance(result, CheckResult)  # the default format
        print(f"{student}: score {result.score} ({result.passed} of {result.total})")
        for item in result.items:
            print(f"  {item.pointer}: {'pass' if item.pass_ else 'fail'}: {item.feedback}")
        stored = service.read(JobOfCheckOutput, check.id)
        reference = service.template_value("p103-slider-flywheel", "inertia_exact")
        print(f"  stored as job {stored.id} (label {stored.label}); I_exact = {reference} kg*m^2")
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:5]))

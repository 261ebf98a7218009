"""mechdyn_client (clients/python, installed by pip) against the real service.

Run by tests/api/python_client.rs as: python python_client.py BASE CLASS_CSV
Each call a grader makes, with its answer checked against an independent
source; exits 1 on the first mismatch, printing what it checked.
"""

import csv
import io
import sys

from mechdyn_client import Mechdyn, MechdynError
from mechdyn_client.generated.models import JobOfFlywheelResult, Variant

BASE, CLASS_CSV = sys.argv[1:3]
# Case F1 (P.103): the exact inertia's closed form by nested brentq, tests/fixtures/cases.
F1_EXACT = 353.52142732201185
# 1 slug·ft² = 14.59390293720636 kg × (0.3048 m)² (NIST SP 811).
SLUG_FT2 = 14.59390293720636 * 0.3048**2
P103 = {
    "mean_speed": "60 rpm",
    "irregularity": 0.04,
    "torques": [
        {"name": "slider resistance", "value": {"segments": [{"from": 0, "to": "pi", "expr": "-500*sin(phi)"}]}},
        {"name": "motor", "balance": True},
    ],
    "reduced_inertia": {"expr": "5*sin(phi)^2"},
    "samples": 0,
}


def close(got: float, want: float, tol: float, what: str) -> None:
    assert abs(got - want) <= tol * abs(want), f"{what}: {got} against {want}"
    print(f"ok {what}: {got}")


with Mechdyn(BASE) as service:
    job = service.post(JobOfFlywheelResult, P103, label="s001")
    close(job.result.inertia_exact, F1_EXACT, 1e-12, "post: typed result, F1's closed form")
    close(service.value(job.id, "/flywheel_inertia/exact"), F1_EXACT, 1e-12, "value by pointer")
    close(service.value(job.id, "inertia_exact", unit="slug*ft^2"), F1_EXACT / SLUG_FT2, 1e-12, "value in slug·ft²")
    assert service.read(JobOfFlywheelResult, job.id).result.to_dict() == job.result.to_dict(), "read back"
    close(service.template_value("p103-slider-flywheel", "inertia_exact"), F1_EXACT, 1e-12, "a template's value")

    rows = service.variants("p103-class", seed=1, count=3, values=["inertia_exact"])
    assert len(rows) == 3 and all(isinstance(r, Variant) and isinstance(r.job, str) for r in rows), rows
    table = list(csv.DictReader(io.StringIO(service.variants_csv("p103-class", seed=1, count=3, values=["inertia_exact"]))))
    for row, line in zip(rows, table):
        # The same variant's reference, typed and as CSV text, and again as the template's value for its parameters.
        typed = float(row.values.additional_properties["inertia_exact"])
        assert float(line["inertia_exact"]) == typed, (row, line)
        again = service.template_value("p103-class", "inertia_exact", row.parameters.additional_properties)
        close(again, typed, 1e-15, f"variant {row.variant} as CSV and by its parameters")
    spanish = service.variants_csv("p103-class", seed=1, count=1, values=["inertia_exact"], decimal_comma=True)
    assert spanish.splitlines()[0].startswith("variant;") and "," in spanish.splitlines()[1], spanish

    with open(CLASS_CSV, encoding="utf-8") as f:
        students = f.read()
    grades = list(csv.DictReader(io.StringIO(service.grade_class("p103-class", students, sigfigs=3))))
    assert len(grades) == len(students.strip().splitlines()) - 1 and {"student", "score"} <= grades[0].keys(), grades
    print(f"ok a class of {len(grades)} graded as CSV")

    try:
        service.post(JobOfFlywheelResult, {**P103, "mean_speed": "60 rmp"})
        raise AssertionError("a unit misspelled was accepted")
    except MechdynError as e:
        assert (e.status, e.type) == (422, "/problems/invalid-request"), e.problem
        assert [x.pointer for x in e.errors] == ["/mean_speed"] and "rpm" in e.errors[0].message, e.errors
        print(f"ok refused: {e}")
    try:
        service.template_value("p103-slider-flywheel", "inertia_exact", {"eps": 3})
        raise AssertionError("eps = 3 was accepted")
    except MechdynError as e:
        assert e.status == 400 and [x.parameter for x in e.errors] == ["eps"], e.problem
        print(f"ok refused: {e}")

with Mechdyn(BASE, language="es") as service:
    try:
        service.template_value("p103-slider-flywheel", "inertia_exact", {"eps": 3})
        raise AssertionError("eps = 3 was accepted")
    except MechdynError as e:
        assert "máximo" in e.errors[0].message, e.errors
        print(f"ok in Spanish: {e}")
print("mechdyn_client: every call checked")

#!/usr/bin/env python3
"""Grade a class through a mechdyn service, with Python's standard library only.

    python3 grade_class.py http://127.0.0.1:8080 p103-class class.csv [--sigfigs 3] > graded.csv

class.csv has a `student` column, the student's parameters or a `variant`
column, and one column per answer named by its pointer into the result
(`inertia_exact`, or `inertia_exact [slug*ft^2]` for bare numbers in that
unit). The graded CSV (student, score, per answer pass and relative_error,
feedback, error) goes to standard output, a summary to standard error.

The POST carries an Idempotency-Key made from the class and the options, so
a retry after a timeout or a 503 is answered once and never grades twice.
"""

import argparse
import csv
import hashlib
import io
import sys
import time
import urllib.error
import urllib.parse
import urllib.request


def grade(base, template, class_csv, options, attempts=5):
    query = urllib.parse.urlencode({k: v for k, v in options.items() if v is not None})
    url = f"{base.rstrip('/')}/v1/templates/{urllib.parse.quote(template)}/grade" + (f"?{query}" if query else "")
    key = hashlib.sha256(f"{url}\n".encode() + class_csv).hexdigest()
    for attempt in range(attempts):
        request = urllib.request.Request(url, data=class_csv, method="POST",
                                         headers={"Content-Type": "text/csv", "Idempotency-Key": key})
        try:
            with urllib.request.urlopen(request, timeout=300) as answer:
                return answer.read().decode("utf-8")
        except urllib.error.HTTPError as e:
            if e.code in (503, 409) and attempt + 1 < attempts:
                time.sleep(float(e.headers.get("Retry-After", "1")))
                continue
            sys.exit(f"grade_class: {e.code} {e.read().decode('utf-8', 'replace')}")
        except (urllib.error.URLError, TimeoutError) as e:
            if attempt + 1 < attempts:
                time.sleep(1)
                continue
            sys.exit(f"grade_class: {e}")
    sys.exit("grade_class: no answer")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("service")
    p.add_argument("template")
    p.add_argument("class_csv")
    for name in ("relative", "absolute", "sigfigs", "zero_level", "reveal"):
        p.add_argument(f"--{name.replace('_', '-')}", dest=name)
    a = p.parse_args()
    with open(a.class_csv, "rb") as f:
        body = f.read()
    options = {k: getattr(a, k) for k in ("relative", "absolute", "sigfigs", "zero_level", "reveal")}
    graded = grade(a.service, a.template, body, options)
    sys.stdout.write(graded)
    rows = list(csv.DictReader(io.StringIO(graded)))
    scores = [float(r["score"]) for r in rows if r["score"]]
    failed = [r["student"] for r in rows if r["error"]]
    mean = sum(scores) / len(scores) if scores else 0.0
    print(f"{len(scores)} students graded, mean score {mean:.3f}; {len(failed)} rows not graded {failed}",
          file=sys.stderr)


if __name__ == "__main__":
    main()

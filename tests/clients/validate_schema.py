"""Validates JSON instances against schemas of an OpenAPI 3.1 document.

Usage: validate_schema.py DOCUMENT.json CASES.json
CASES.json is a list of {"what": TEXT, "schema": "#/components/schemas/NAME"
(or any JSON pointer into the document), "instance": VALUE}. Each instance
is validated with the `jsonschema` package (PyPI; JSON Schema 2020-12, the
dialect of OpenAPI 3.1) against the document's schema at that pointer, its
$refs resolved within the document. Prints one line per failure and a
summary; exits 1 if any failed, 3 if `jsonschema` is missing.
"""

import json
import sys

try:
    import jsonschema
except ImportError:
    print("jsonschema is not installed")
    sys.exit(3)


def main():
    document = json.load(open(sys.argv[1]))
    cases = json.load(open(sys.argv[2]))
    failed = 0
    for case in cases:
        # The whole document as the root schema, so that "#/components/…" resolves in it;
        # its other members (openapi, info, paths) are keywords JSON Schema ignores.
        root = dict(document)
        root["$ref"] = case["schema"]
        root["$schema"] = "https://json-schema.org/draft/2020-12/schema"
        validator = jsonschema.Draft202012Validator(root)
        errors = sorted(validator.iter_errors(case["instance"]), key=lambda e: list(e.absolute_path))
        for e in errors[:3]:
            failed += 1
            where = "/" + "/".join(str(p) for p in e.absolute_path)
            print(f"{case['what']}: at {where}: {e.message[:300]}")
    print(f"{len(cases)} instances validated, {failed} errors")
    sys.exit(1 if failed else 0)


main()

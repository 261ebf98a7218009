"""The service through a client generated from its own document (issue 49).

Run by tests/api/generated.rs as: python generated_client.py BASE CLIENT_DIR CASES
- BASE: the running service's URL; CLIENT_DIR: where openapi-python-client
  generated the package `mechdyn_client` from BASE/openapi.json;
- CASES: a JSON list of {"what", "path", "body"}: the problem library's
  requests and the built-in templates' requests.

With the generated client: every kind's documented request example and every
case is posted typed (the request model's to_dict is the body), its typed
answer's to_dict is the JSON received, and the job read back is typed as its
kind's job (`Job_<kind>`, its `result` the kind's result class). A number, a
text, a list and a null part, the values as CSV, the result's table, a plot,
a class graded from a CSV body and a cam's profile.dxf are read through the
generated calls. Beside it, openapi-core validates every answer received,
errors included, against the document. Prints what it checked; exits 1 on
the first mismatch.
"""

import importlib
import json
import re
import sys

import httpx
from openapi_core import Config, OpenAPI
from openapi_core.deserializing.media_types.util import json_loads, plain_loads
from openapi_core.contrib.requests import RequestsOpenAPIRequest, RequestsOpenAPIResponse
import requests

BASE, CLIENT_DIR, CASES = sys.argv[1:4]
sys.path.insert(0, CLIENT_DIR)

from mechdyn_client import Client, models  # noqa: E402
from mechdyn_client.api.grading import post_template_grade  # noqa: E402
from mechdyn_client.api.jobs import (  # noqa: E402
    get_job, get_job_file, get_job_plot, get_job_result_csv, get_job_result_part,
    get_job_values_csv, list_job_plots)
from mechdyn_client.types import File  # noqa: E402

DOC = requests.get(BASE + "/openapi.json", timeout=30).json()
# openapi-core reads text/plain and text/html as text, a few JSON types as JSON and every other
# type as bytes: these are text, and RFC 7807's problem document is JSON (the +json suffix).
READ = {t: plain_loads for t in ["text/csv", "image/svg+xml", "application/dxf"]}
READ["application/problem+json"] = json_loads
OPENAPI = OpenAPI.from_dict(DOC, config=Config(extra_media_type_deserializers=READ))
SEEN = []


def record(response: httpx.Response):
    """Every answer the generated client receives, kept for openapi-core."""
    response.read()
    SEEN.append(response)


CLIENT = Client(base_url=BASE, timeout=httpx.Timeout(120), raise_on_unexpected_status=True,
                httpx_args={"event_hooks": {"response": [record]}})


def pascal(schema: str) -> str:
    """The generated class of a schema: `JobOf_FlywheelResult` -> `JobOfFlywheelResult`."""
    return "".join(p[:1].upper() + p[1:] for p in re.split(r"[^A-Za-z0-9]+", schema) if p)


def ref_name(media: dict) -> str:
    return media["schema"]["$ref"].rsplit("/", 1)[1]


def fail(what: str, detail) -> None:
    print(f"FAIL {what}: {str(detail)[:1500]}")
    sys.exit(1)


def kind_posts():
    """Each kind's POST: path -> (module, request schema, JobOf schema, kind, result schema)."""
    posts = {}
    for path, item in DOC["paths"].items():
        op = item.get("post", {})
        created = op.get("responses", {}).get("201", {}).get("content", {}).get("application/json")
        if not created or "$ref" not in created.get("schema", {}):
            continue
        tag = re.sub(r"[^a-z0-9]+", "_", op["tags"][0].lower())
        module = importlib.import_module(f"mechdyn_client.api.{tag}.{op['operationId']}")
        request = ref_name(op["requestBody"]["content"]["application/json"])
        job = ref_name(created)
        if not job.startswith("JobOf_"):
            continue  # a template is created, not a job
        result = DOC["components"]["schemas"][job]["properties"]["result"]["$ref"].rsplit("/", 1)[1]
        posts[path] = (module, request, job, created["example"]["kind"], result)
    return posts


def classes(schema: str) -> set:
    """The generated classes a value of `schema` may be: its own, or one of its `oneOf`'s."""
    union = DOC["components"]["schemas"][schema].get("oneOf", [])
    return {pascal(schema)} | {pascal(s["$ref"].rsplit("/", 1)[1]) for s in union if "$ref" in s}


def post_typed(posts, path: str, body: dict, what: str) -> str:
    module, request, job, kind, result = posts[path]
    typed = getattr(models, pascal(request)).from_dict(body)
    if typed.to_dict() != body:
        fail(what, f"the request model changes the body: {typed.to_dict()} != {body}")
    answer = module.sync_detailed(client=CLIENT, body=typed)
    if answer.status_code != 201:
        fail(what, f"{answer.status_code}: {answer.content[:300]!r}")
    sent = json.loads(answer.content)
    if type(answer.parsed).__name__ != pascal(job) or answer.parsed.to_dict() != sent:
        fail(what, f"the typed answer ({type(answer.parsed).__name__}) differs from the JSON")
    read = get_job.sync_detailed(id=sent["id"], client=CLIENT)
    if type(read.parsed).__name__ != pascal(f"Job_{kind}") or type(read.parsed.result).__name__ not in classes(result):
        fail(what, f"read back as {type(read.parsed).__name__} with {type(read.parsed.result).__name__}")
    if read.parsed.to_dict() != json.loads(read.content):
        fail(what, "the job read back, typed, differs from its JSON")
    return sent["id"]


def text(parsed) -> str:
    """A text answer read as bytes (the generator's octet-stream), as text."""
    return parsed.decode() if isinstance(parsed, bytes) else parsed


def first(value, test, pointer=""):
    """The pointer of the first value of the result that passes `test`."""
    if test(value):
        return pointer, value
    items = value.items() if isinstance(value, dict) else enumerate(value) if isinstance(value, list) else []
    for key, item in items:
        found = first(item, test, f"{pointer}/{key}")
        if found:
            return found
    return None


def parts(job_id: str, result: dict, what: str):
    """A number, a text, a list and a null of the result, read as the JSON has them."""
    as_json = CLIENT.with_headers({"Accept": "application/json"})
    tests = {
        "number": lambda v: isinstance(v, float),
        "text": lambda v: isinstance(v, str),
        "list": lambda v: isinstance(v, list) and 0 < len(v) < 50,
        "null": lambda v: v is None,
    }
    read = []
    for name, test in tests.items():
        found = first(result, test)
        if found is None:
            continue
        pointer, value = found
        got = get_job_result_part.sync_detailed(id=job_id, pointer=pointer.lstrip("/"), client=as_json)
        if got.status_code != 200 or got.parsed != value:
            fail(what, f"the {name} part {pointer}: {got.status_code} {got.content[:200]!r}, expected {value!r}")
        read.append(name)
    return read


def every_operation_generated():
    """Each operation of the document has its generated call."""
    missing = []
    for path, item in DOC["paths"].items():
        for method, op in item.items():
            if not isinstance(op, dict) or "operationId" not in op:
                continue
            tag = re.sub(r"[^a-z0-9]+", "_", op["tags"][0].lower())
            try:
                module = importlib.import_module(f"mechdyn_client.api.{tag}.{op['operationId']}")
                assert callable(module.sync_detailed)
            except (ImportError, AttributeError, AssertionError):
                missing.append(f"{method.upper()} {path}")
    if missing:
        fail("operations not generated", missing)
    return sum(1 for item in DOC["paths"].values() for op in item.values() if isinstance(op, dict))


def main():
    print(f"every one of the document's {every_operation_generated()} operations has its generated call")
    posts = kind_posts()
    cases = [{"what": f"the documented example of {path}",
              "path": path, "body": DOC["components"]["schemas"][posts[path][1]]["example"]} for path in posts]
    cases += json.load(open(CASES))
    ids = {}
    for case in cases:
        ids.setdefault(case["path"], post_typed(posts, case["path"], case["body"], case["what"]))
    print(f"{len(cases)} requests of {len(posts)} kinds posted and read back typed")

    flywheel = ids["/v1/flywheel"]
    result = json.loads(get_job.sync_detailed(id=flywheel, client=CLIENT).content)["result"]
    read = set()
    for job_id in ids.values():
        job = json.loads(get_job.sync_detailed(id=job_id, client=CLIENT).content)
        read.update(parts(job_id, job["result"], job["kind"]))
    if read != {"number", "text", "list", "null"}:
        fail("parts", f"only {read} found to read")
    values = text(get_job_values_csv.sync_detailed(id=flywheel, client=CLIENT).parsed)
    exact = next(line for line in values.splitlines() if line.startswith("/inertia_exact,"))
    if float(exact.split(",")[1]) != result["inertia_exact"]:
        fail("values.csv", exact)
    table = text(get_job_result_csv.sync_detailed(id=flywheel, client=CLIENT).parsed)
    plots = list_job_plots.sync_detailed(id=flywheel, client=CLIENT).parsed
    name = plots.plots[0].name
    svg = text(get_job_plot.sync_detailed(id=flywheel, name=name, client=CLIENT).parsed)
    if not svg.lstrip().startswith("<svg") or len(table.splitlines()) < 3:
        fail("plot and table", f"{svg[:80]!r} {table[:80]!r}")
    cam = ids.get("/v1/cams")
    dxf = text(get_job_file.sync_detailed(id=cam, name="profile.dxf", client=CLIENT).parsed)
    if "LWPOLYLINE" not in dxf and "POLYLINE" not in dxf:
        fail("profile.dxf", dxf[:200])
    csv = "student,variant,inertia_exact\ns1,1,353.52\ns2,2,1\n"
    graded = post_template_grade.sync_detailed(
        id="p103-class", client=CLIENT, body=File(payload=csv.encode(), mime_type="text/csv"))
    rows = text(graded.parsed).splitlines()
    if graded.status_code != 200 or len(rows) != 3 or not rows[0].startswith("student,score"):
        fail("grade", rows)
    print("parts (number, text, list, null), values.csv, result.csv, a plot, profile.dxf and a graded class read")

    other_routes(ids)
    validate()


def other_routes(ids):
    """Every other route of the document, and answers besides 2xx made to happen: each validated below."""
    job, cam = ids["/v1/flywheel"], ids["/v1/cams"]
    gone = ids["/v1/mobility"]
    p103 = json.dumps(DOC["components"]["schemas"][kind_posts()["/v1/flywheel"][1]]["example"]).encode()
    media = DOC["paths"]["/v1/templates"]["post"]["requestBody"]["content"]["application/json"]
    template = media.get("example") or DOC["components"]["schemas"][ref_name(media)]["example"]
    template = dict(template, id="generated-client-template")
    asks = [
        ("GET", "/", None, None), ("GET", f"/jobs/{job}", None, None), ("GET", "/templates/p103-class", None, None),
        ("GET", "/healthz", None, None), ("GET", "/readyz", None, None), ("GET", "/metrics", None, None),
        ("GET", "/favicon.ico", None, None),
        ("GET", "/v1/jobs?kind=flywheel&limit=3", None, None), ("GET", "/v1/templates", None, None),
        ("GET", "/v1/templates/p103-class", None, None), ("GET", "/v1/templates/p103-class/variants?count=2", None, None),
        ("GET", "/v1/templates/p103-class/job?F=1200", None, None),
        ("GET", "/v1/templates/p103-class/result/inertia_exact", None, None),
        ("POST", "/v1/templates/p103-class/table", "text/csv", b"F\n1000\n1200\n"),
        ("GET", f"/v1/jobs/{job}/result/inertia_exact", None, None),
        ("GET", f"/v1/jobs/{job}/values", None, None), ("GET", f"/v1/jobs/{job}/plots", None, None),
        ("GET", f"/v1/jobs/{cam}/result.csv", None, None),
        ("POST", "/v1/flywheel", "application/json", p103, {"prefer": "respond-async"}),
        ("DELETE", f"/v1/jobs/{gone}", None, None), ("GET", f"/v1/jobs/{gone}", None, None),
        ("GET", f"/v1/jobs/{job}/result/no_such_field", None, None),
        ("GET", "/v1/jobs?limit=0", None, None),
        ("POST", "/v1/flywheel", "text/plain", b"{}"),
        ("POST", "/v1/flywheel", "application/json", b"{nope"),
        ("POST", "/v1/flywheel", "application/json", json.dumps({"mean_speed": "60 furlongs"}).encode()),
        ("GET", f"/v1/jobs/{job}/plots/no_such_plot.svg", None, None),
        ("GET", f"/v1/jobs/{job}/no_such_file.dxf", None, None),
        ("GET", f"/v1/jobs/{job}/values?format=xml", None, None),
        ("GET", "/v1/templates/no-such-template", None, None),
        ("POST", "/v1/templates", "application/json", json.dumps(template).encode()),
        ("POST", "/v1/flywheel", "application/json", b" " * (2 << 20)),
    ]
    for method, path, content_type, body, *extra in asks:
        headers = {"content-type": content_type} if content_type else {}
        headers.update(extra[0] if extra else {})
        CLIENT.get_httpx_client().request(method, path, content=body, headers=headers)
    statuses = {r.status_code for r in SEEN}
    if not {200, 201, 202, 204, 400, 404, 413, 415, 422} <= statuses:
        fail("statuses", sorted(statuses))
    if any(r.status_code >= 500 for r in SEEN):
        fail("a 5xx", [(str(r.request.url), r.status_code) for r in SEEN if r.status_code >= 500])


def validate():
    """openapi-core: every answer received against the document."""
    checked = {}
    for response in SEEN:
        request = response.request
        prepared = requests.Request(request.method, str(request.url), headers=dict(request.headers),
                                    data=request.content or None).prepare()
        answer = requests.Response()
        answer.status_code, answer._content = response.status_code, response.content
        answer.headers.update(response.headers)
        answer.request = prepared
        try:
            OPENAPI.validate_response(RequestsOpenAPIRequest(prepared), RequestsOpenAPIResponse(answer))
        except Exception as e:  # noqa: BLE001 - every mismatch is reported with its route
            causes = getattr(e, "__cause__", None)
            fail(f"openapi-core on {request.method} {request.url.path} {response.status_code}",
                 f"{e!r} {str(causes)[:600]} {response.content[:300]!r}")
        route = f"{request.method} {response.status_code} {response.headers.get('content-type', '').split(';')[0]}"
        checked[route] = checked.get(route, 0) + 1
    print(f"openapi-core validated {len(SEEN)} answers: " + ", ".join(sorted(checked)))


main()

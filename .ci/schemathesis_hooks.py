"""Loaded by schemathesis before it runs (SCHEMATHESIS_HOOKS, .ci/schemathesis).

CPython 3.11.7's ast.parse raises "SystemError: AST constructor recursion
depth mismatch" when called deep in the stack (CPython gh-106905, fixed in
later releases); Hypothesis calls it to describe lambdas while building the
strategies of the document's nested schemas, and schemathesis reported it as a
runtime error of POST /v1/gears/train with every seed once the mechanism's
schema gained `dimensions` and `track`. A higher recursion limit keeps the
parser clear of it; nothing of the service is involved.
"""

import sys

sys.setrecursionlimit(max(sys.getrecursionlimit(), 20000))

"""mechdyn's Python client.

`Mechdyn` (in `service`) is the calls a grader makes, typed; `generated` is
the whole API as openapi-python-client makes it from the service's document
(`clients/python/generate`), with its models for every request and result.
"""

from . import generated
from .service import ROUTES, FieldProblem, Mechdyn, MechdynError

__all__ = ["ROUTES", "FieldProblem", "Mechdyn", "MechdynError", "generated"]

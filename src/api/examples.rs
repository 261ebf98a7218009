//! Real examples in the OpenAPI document: the 201 of every POST shows the job
//! its request example gives, computed by the engine when the document is
//! built (long arrays shortened to their first items, said in the text), so
//! the docs never show a result the service would not give. Also the units
//! of the results and the list of kinds, from the registry.

use super::kind::{self, AnyKind};
use crate::kind::limits::Limits;
use serde_json::{Value, json};

/// Items kept of a long array in an example.
const KEEP: usize = 3;

/// The result of the kind's request example.
fn run(kind: &dyn AnyKind, request: &Value, kinds: &kind::Registry) -> Option<Value> {
    serde_json::from_slice(&kind.solve(request.to_string(), &Limits::default(), kinds).ok()?).ok()
}

/// `doc` (the OpenAPI document as JSON) with what the registry knows: every
/// POST's 201 example, the units of every result's fields (`x-units`: JSON
/// pointer patterns, `*` for any index or key, and units, `1` for a pure
/// number), and the kinds the jobs list can filter on.
pub fn add(doc: &mut Value, kinds: &kind::Registry) {
    let mut names = Vec::new();
    for kind in kinds.iter() {
        let units: serde_json::Map<String, Value> =
            kind.units().iter().map(|(pattern, unit)| (pattern.to_string(), json!(unit))).collect();
        doc["components"]["schemas"][kind.result_schema()]["x-units"] = Value::Object(units);
        names.push(json!(kind.name()));
        let request = doc["components"]["schemas"][kind.request_schema()]["example"].clone();
        let Some(mut result) = run(kind, &request, kinds) else { continue };
        shorten(&mut result);
        if let Some(reference) = result.get_mut("job").filter(|j| j.is_null()) {
            // A check's reference job, computed here without a store: an id as the service gives one.
            *reference = json!("7c9e6679-7425-40de-944b-e07fc1f90ae7");
        }
        let job = json!({
            "id": "0d1e5d8a-6a3c-4f4e-9a53-2f1c0b7e9d41",
            "kind": kind.name(),
            "status": "done",
            "created_at": "2026-11-23T12:00:00.000000Z",
            "request": request,
            "result": result,
            "timing": {"engine_us": 250},
            "engine_version": env!("CARGO_PKG_VERSION"),
        });
        let created = &mut doc["paths"][kind.path()]["post"]["responses"]["201"];
        created["content"]["application/json"]["example"] = job;
        if let Some(d) = created["description"].as_str() {
            created["description"] =
                format!("{d} (the example is the job of the request's example; arrays are shortened to {KEEP} items)")
                    .into();
        }
    }
    list_kinds(doc, names);
    document_rest_of_path(doc);
}

/// A path routed with `{*NAME}` (the rest of the path) is documented as
/// `{NAME}`; the plot's, routed as `{name}`, as `{name}.svg`.
fn document_rest_of_path(doc: &mut Value) {
    let Some(paths) = doc["paths"].as_object_mut() else { return };
    let routed: Vec<String> = paths.keys().filter(|p| p.contains("{*")).cloned().collect();
    for path in routed {
        if let Some(item) = paths.remove(&path) {
            paths.insert(path.replace("{*", "{"), item);
        }
    }
    if let Some(item) = paths.remove(super::plots::ROUTED) {
        paths.insert(super::plots::DOCUMENTED.into(), item);
    }
}

/// The jobs list's `kind` parameter: one of the registry's names.
fn list_kinds(doc: &mut Value, kinds: Vec<Value>) {
    let Some(parameters) = doc["paths"]["/v1/jobs"]["get"]["parameters"].as_array_mut() else { return };
    for p in parameters.iter_mut().filter(|p| p["name"] == "kind") {
        p["schema"]["enum"] = Value::Array(kinds.clone());
    }
}

/// Every array longer than [`KEEP`] cut to its first items.
fn shorten(v: &mut Value) {
    match v {
        Value::Array(items) => {
            items.truncate(KEEP);
            items.iter_mut().for_each(shorten);
        }
        Value::Object(map) => map.values_mut().for_each(shorten),
        _ => {}
    }
}

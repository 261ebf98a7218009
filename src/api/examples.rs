//! Real examples in the OpenAPI document: the 201 of every POST shows the job
//! its request example gives, computed by the engine when the document is
//! built (long arrays shortened to their first items, said in the text), so
//! the docs never show a result the service would not give.

use super::problem::{ApiError, FieldError};
use super::{dynamics, equivalent, flywheel, gear_train, gears, kinetostatics, rotor};
use serde::Serialize;
use serde::de::DeserializeOwned;
use serde_json::{Value, json};

/// Items kept of a long array in an example.
const KEEP: usize = 3;

/// A POST's path, its job kind, the schema of its request, and how to compute it.
type Example = (&'static str, &'static str, &'static str, fn(&Value) -> Option<Value>);

const EXAMPLES: &[Example] = &[
    ("/v1/flywheel", "flywheel", "FlywheelRequest", |v| run(v, flywheel::compute)),
    ("/v1/kinetostatics", "kinetostatics", "KinetostaticsRequest", |v| run(v, kinetostatics::compute)),
    ("/v1/dynamics", "dynamics", "DynamicsRequest", |v| run(v, dynamics::compute)),
    ("/v1/gears/geometry", "gears", "GearRequest", |v| run(v, gears::compute)),
    ("/v1/gears/train", "gear_train", "TrainRequest", |v| run(v, gear_train::compute)),
    ("/v1/equivalent-masses", "equivalent_masses", "EquivalentRequest", |v| run(v, equivalent::compute)),
    ("/v1/rotor", "rotor", "RotorRequest", |v| run(v, rotor::compute)),
];

fn run<T: DeserializeOwned, R: Serialize>(
    request: &Value,
    compute: fn(&T, Vec<FieldError>) -> Result<R, ApiError>,
) -> Option<Value> {
    let body = super::json::parse::<T>(request.to_string()).ok()?;
    serde_json::to_value(compute(&body.value, body.unknown).ok()?).ok()
}

/// `doc` (the OpenAPI document as JSON) with every POST's 201 example.
pub fn add(doc: &mut Value) {
    for (path, kind, schema, compute) in EXAMPLES {
        let request = doc["components"]["schemas"][schema]["example"].clone();
        let Some(mut result) = compute(&request) else { continue };
        shorten(&mut result);
        let job = json!({
            "id": "0d1e5d8a-6a3c-4f4e-9a53-2f1c0b7e9d41",
            "kind": kind,
            "created_at": "2026-11-23T12:00:00.000000Z",
            "request": request,
            "result": result,
            "timing": {"engine_us": 250},
            "engine_version": env!("CARGO_PKG_VERSION"),
        });
        let created = &mut doc["paths"][path]["post"]["responses"]["201"];
        created["content"]["application/json"]["example"] = job;
        if let Some(d) = created["description"].as_str() {
            created["description"] =
                format!("{d} (the example is the job of the request's example; arrays are shortened to {KEEP} items)")
                    .into();
        }
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

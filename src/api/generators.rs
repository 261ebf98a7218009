//! The document as the clients' own generators read it (contract, part
//! four: "The document, for generators"), made from the registry:
//! - a stored job typed by its kind: `Job` is one of `Job_<kind>` (the same
//!   fields, `kind` that kind's name, `result` its result schema or null
//!   until it is done), told apart by `kind` — a discriminator with its
//!   mapping, which openapi-python-client and openapi-typescript read;
//! - a job's files in the content types the service serves them in;
//! - a body that is not JSON (a class's CSV) as `format: binary`, which
//!   openapi-python-client sends as the bytes it is given (as a plain
//!   string it generated a call that failed on its own argument);
//! - the `?label=` and `Idempotency-Key` of every POST that creates a job
//!   (the middleware reads them for any POST: [`super::label`],
//!   [`super::idempotency`]), so that a generated call can send them;
//! - a member named `d` under `patternProperties`: openapi-python-client's
//!   `from_dict` keeps the member dict in a local `d`, which a member `d`
//!   overwrote (its generated parser then failed on every rotor answer). The
//!   wire is unchanged, the member still validated; the generated class
//!   reads it as `support["d"]`.

use super::kind::{self, AnyKind};
use serde_json::{Map, Value, json};

/// The stored job's schema name, and the prefix of its kinds' variants.
const JOB: &str = "Job";

pub fn add(doc: &mut Value, kinds: &kind::Registry) {
    typed_jobs(doc, kinds);
    file_types(doc, kinds);
    binary_bodies(doc);
    post_parameters(doc);
    shadowing_members(doc);
}

/// `Job` as the one of its kinds' jobs that its `kind` names.
fn typed_jobs(doc: &mut Value, kinds: &kind::Registry) {
    let schemas = &mut doc["components"]["schemas"];
    let common = schemas[JOB].clone();
    if !common.is_object() {
        return;
    }
    let (mut one_of, mut mapping) = (Vec::new(), Map::new());
    for kind in kinds.iter() {
        let name = format!("{JOB}_{}", kind.name());
        schemas[&name] = variant(&common, kind);
        let reference = format!("#/components/schemas/{name}");
        one_of.push(json!({ "$ref": reference }));
        mapping.insert(kind.name().into(), reference.into());
    }
    schemas[JOB] = json!({
        "description": common["description"],
        "oneOf": one_of,
        "discriminator": {"propertyName": "kind", "mapping": mapping},
    });
}

/// The stored job's fields with `kind` this kind's name and `result` its schema.
fn variant(common: &Value, kind: &dyn AnyKind) -> Value {
    let mut job = common.clone();
    job["title"] = format!("{JOB}_{}", kind.name()).into();
    job["description"] =
        format!("A stored job of kind `{}`: its `result` is {}.", kind.name(), kind.result_schema()).into();
    job["properties"]["kind"] = json!({"type": "string", "enum": [kind.name()]});
    let described = job["properties"]["result"]["description"].clone();
    job["properties"]["result"] = json!({
        "description": described,
        "oneOf": [{"$ref": format!("#/components/schemas/{}", kind.result_schema())}, {"type": "null"}],
    });
    job
}

/// The file route's answer in each content type a kind's files have.
fn file_types(doc: &mut Value, kinds: &kind::Registry) {
    let ok = &mut doc["paths"]["/v1/jobs/{id}/{name}"]["get"]["responses"]["200"];
    if !ok.is_object() {
        return;
    }
    let mut content = Map::new();
    for (_, content_type) in kinds.iter().flat_map(|k| k.files()) {
        content.insert((*content_type).into(), json!({"schema": {"type": "string"}}));
    }
    if !content.is_empty() {
        ok["content"] = Value::Object(content);
    }
}

/// Every request body's non-JSON content (a string) marked `format: binary`.
fn binary_bodies(doc: &mut Value) {
    let Some(paths) = doc["paths"].as_object_mut() else { return };
    let operations = paths.values_mut().filter_map(Value::as_object_mut).flat_map(|item| item.values_mut());
    for operation in operations {
        let Some(content) = operation.pointer_mut("/requestBody/content").and_then(Value::as_object_mut) else {
            continue;
        };
        for (content_type, media) in content.iter_mut().filter(|(t, _)| !t.ends_with("json")) {
            if media["schema"]["type"] == "string" {
                media["schema"]["format"] = "binary".into();
                media["schema"]["description"] = format!("The {content_type} text, as bytes").into();
            }
        }
    }
}

/// `label` (query) and `Idempotency-Key` (header) on every POST that creates a job.
fn post_parameters(doc: &mut Value) {
    let label = json!({
        "name": "label", "in": "query", "required": false,
        "schema": {
            "type": "string", "minLength": 1, "maxLength": super::label::MAX_LABEL,
            // No control character, nor a bidirectional embedding, override, isolate or mark.
            "pattern": "^[^\\u0000-\\u001F\\u007F-\\u009F\\u061C\\u200E\\u200F\\u202A-\\u202E\\u2066-\\u2069]+$",
        },
        "description": "A label stored with the job this POST creates (a student's id): `GET /v1/jobs?label=` lists them",
    });
    let key = json!({
        "name": "Idempotency-Key", "in": "header", "required": false,
        // Visible ASCII, spaces inside only (the key is trimmed).
        "schema": {"type": "string", "maxLength": super::idempotency::MAX_KEY, "pattern": "^[!-~](?:[ -~]*[!-~])?$"},
        "description": "A retry with the same key and body gets the first answer again (`Idempotent-Replayed: true`), \
                        nothing computed or stored twice; the same key with another body is a 422. Kept 7 days",
    });
    let Some(paths) = doc["paths"].as_object_mut() else { return };
    let creates = |post: &Value| {
        let created = post.pointer("/responses/201/content/application~1json/schema/$ref").and_then(Value::as_str);
        created.is_some_and(|r| r.contains("/JobOf_"))
    };
    for post in paths.values_mut().filter_map(|item| item.get_mut("post")).filter(|post| creates(post)) {
        let parameters = post["parameters"].as_array().cloned().unwrap_or_default();
        let named = |name: &str| parameters.iter().any(|p| p["name"] == name);
        let mut added = parameters.clone();
        added.extend([&label, &key].into_iter().filter(|p| !named(p["name"].as_str().unwrap_or(""))).cloned());
        post["parameters"] = Value::Array(added);
    }
}

/// Every schema's member `d` moved to `patternProperties` (see the module's docs).
fn shadowing_members(doc: &mut Value) {
    let Some(schemas) = doc["components"]["schemas"].as_object_mut() else { return };
    for schema in schemas.values_mut() {
        let Some(d) = schema.get_mut("properties").and_then(|p| p.as_object_mut()).and_then(|p| p.remove("d")) else {
            continue;
        };
        // Still `required` where it was: a validator asks for it all the same.
        schema["patternProperties"] = json!({ "^d$": d });
    }
}

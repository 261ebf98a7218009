//! `?errors=text`: a spreadsheet's way to read why. LibreOffice's
//! `SERVICIOWEB()` / Excel's `WEBSERVICE()` turn any 4xx or 5xx into
//! `#¡VALOR!` and show nothing of the answer; with `errors=text` an error
//! comes back as 200 `text/plain`, one line in the asker's language (each
//! field's message after its parameter's name or pointer, or the
//! problem's detail), and its true status in the `Mechdyn-Status` header,
//! so that the cell shows the reason. Answers that are not errors are left as they are.

use axum::body::{Body, to_bytes};
use axum::extract::Request;
use axum::http::{HeaderName, HeaderValue, StatusCode, header};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};
use serde_json::Value;

/// The header that carries an error's own status.
pub const STATUS: HeaderName = HeaderName::from_static("mechdyn-status");
/// Most bytes of a problem document read to make its line.
const MAX_PROBLEM: usize = 1 << 20;

/// The middleware.
pub async fn as_text(req: Request, next: Next) -> Response {
    let asked = req.uri().query().is_some_and(|q| q.split('&').any(|pair| pair == "errors=text"));
    let response = next.run(req).await;
    let problem = response.headers().get(header::CONTENT_TYPE).is_some_and(|v| v == "application/problem+json");
    if !asked || !problem {
        return response;
    }
    let (mut parts, body) = response.into_parts();
    let Ok(bytes) = to_bytes(body, MAX_PROBLEM).await else {
        return (StatusCode::OK, [(STATUS, parts.status.as_str().to_string())], "error").into_response();
    };
    let line = serde_json::from_slice::<Value>(&bytes).map(|p| line(&p)).unwrap_or_default();
    parts.headers.insert(STATUS, HeaderValue::from(parts.status.as_u16()));
    parts.headers.insert(header::CONTENT_TYPE, HeaderValue::from_static("text/plain; charset=utf-8"));
    parts.headers.remove(header::CONTENT_LENGTH);
    parts.status = StatusCode::OK;
    Response::from_parts(parts, Body::from(line))
}

/// A problem document as one line: each field's message after its
/// parameter's name (or its pointer), else the detail, else the title.
fn line(problem: &Value) -> String {
    let text = |v: &Value| v.as_str().map(str::to_string);
    let fields: Vec<String> = problem["errors"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|e| {
            let message = text(&e["message"])?;
            let place = text(&e["parameter"]).or_else(|| text(&e["pointer"])).filter(|p| !p.is_empty());
            Some(place.map_or(message.clone(), |p| format!("{p}: {message}")))
        })
        .collect();
    if !fields.is_empty() {
        return fields.join("; ");
    }
    text(&problem["detail"]).or_else(|| text(&problem["title"])).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn a_problem_reads_as_its_fields_or_its_detail() {
        let fields = json!({"title": "Invalid", "detail": "2 errors", "errors": [
            {"pointer": "/irregularity", "parameter": "eps", "message": "debe estar entre 0 y 1"},
            {"pointer": "/mean_speed", "message": "falta"}]});
        assert_eq!(line(&fields), "eps: debe estar entre 0 y 1; /mean_speed: falta");
        assert_eq!(line(&json!({"title": "No encontrado", "detail": "no hay tal trabajo"})), "no hay tal trabajo");
        assert_eq!(line(&json!({"title": "No encontrado"})), "No encontrado");
    }
}

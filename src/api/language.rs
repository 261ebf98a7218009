//! The language of each answer: `?lang=` (`es`, `en`), else the client's
//! `Accept-Language`, else English ([`Lang::negotiate`]), held for the
//! request's task so that every error, page and plot rendered below speaks
//! it; the answer says which (`Content-Language`) and that it depends on
//! the header (`Vary: Accept-Language`). Numbers and JSON fields do not
//! change with it; `?decimal=comma` is what writes decimal commas.

use crate::i18n::{self, Lang};
use axum::extract::Request;
use axum::http::{HeaderValue, header};
use axum::middleware::Next;
use axum::response::Response;

/// The middleware: negotiates, runs the rest in that language, labels the answer.
pub async fn in_language(req: Request, next: Next) -> Response {
    let lang = of(&req);
    let mut response = i18n::within(lang, next.run(req)).await;
    let headers = response.headers_mut();
    headers.insert(header::CONTENT_LANGUAGE, HeaderValue::from_static(lang.tag()));
    headers.append(header::VARY, HeaderValue::from_static("accept-language"));
    response
}

/// The language `req` asks for.
pub fn of(req: &Request) -> Lang {
    let query = req.uri().query().unwrap_or("");
    let asked = query.split('&').find_map(|pair| pair.strip_prefix("lang="));
    let accept = req.headers().get(header::ACCEPT_LANGUAGE).and_then(|v| v.to_str().ok());
    Lang::negotiate(asked, accept)
}

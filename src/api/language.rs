//! The language of each answer: `?lang=` (`es`, `en`), else the page
//! language the browser was given (the `mechdyn_lang` cookie), else the
//! client's `Accept-Language`, else English ([`Lang::negotiate`]), held for
//! the request's task so that every error, page and plot rendered below
//! speaks it; the answer says which (`Content-Language`) and that it
//! depends on those headers (`Vary`). A page asked with `?lang=` sets the
//! cookie, so that the language sticks to every link, form, plot and
//! redirect the browser follows from it. Numbers and JSON fields do not
//! change with it; `?decimal=comma` is what writes decimal commas.

use crate::i18n::{self, Lang};
use axum::extract::Request;
use axum::http::{HeaderValue, header};
use axum::middleware::Next;
use axum::response::Response;

/// The middleware: negotiates, runs the rest in that language, labels the answer.
pub async fn in_language(req: Request, next: Next) -> Response {
    let lang = of(&req);
    let sticks = asked(&req).and_then(Lang::of).is_some() && super::pages::is_page(req.uri().path());
    let mut response = i18n::within(lang, next.run(req)).await;
    let headers = response.headers_mut();
    headers.insert(header::CONTENT_LANGUAGE, HeaderValue::from_static(lang.tag()));
    headers.append(header::VARY, HeaderValue::from_static("accept-language, cookie"));
    if sticks {
        let cookie = format!("{COOKIE}={}; Path=/; Max-Age=31536000; SameSite=Lax", lang.tag());
        headers.append(header::SET_COOKIE, HeaderValue::from_str(&cookie).expect("a cookie of ASCII"));
    }
    response
}

/// The cookie that keeps a browser's page language.
const COOKIE: &str = "mechdyn_lang";

/// The language `req` asks for.
pub fn of(req: &Request) -> Lang {
    let kept = || {
        let cookies = req.headers().get_all(header::COOKIE).into_iter().filter_map(|v| v.to_str().ok());
        cookies.flat_map(|v| v.split(';')).find_map(|c| c.trim().strip_prefix(COOKIE)?.strip_prefix('='))
    };
    let accept = req.headers().get(header::ACCEPT_LANGUAGE).and_then(|v| v.to_str().ok());
    Lang::negotiate(asked(req).or_else(kept), accept)
}

/// `?lang=`, when the query gives it.
fn asked(req: &Request) -> Option<&str> {
    req.uri().query().unwrap_or("").split('&').find_map(|pair| pair.strip_prefix("lang="))
}

//! The frame of every page: one stylesheet in the page (no external
//! resource, no script), a viewport for phones, a print style, and the
//! answer's headers (a Content-Security-Policy that allows no script and
//! nothing from elsewhere). maud escapes every text put in a page.

use crate::i18n::{self, Msg, tr};
use crate::kind::problem::{ApiError, FieldError};
use axum::http::{HeaderValue, StatusCode, header};
use axum::response::{IntoResponse, Response};
use maud::{DOCTYPE, Markup, PreEscaped, html};

const CSS: &str = r#"
:root { --ink: #1b1b1b; --muted: #5b5b5b; --line: #d9d9d9; --link: #0b5cad; --warn: #8a4b00; --bg: #fafafa; }
* { box-sizing: border-box; }
body { margin: 0; font: 16px/1.5 system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif; color: var(--ink); background: #fff; }
header { border-bottom: 1px solid var(--line); background: var(--bg); }
nav { max-width: 70rem; margin: 0 auto; padding: .6rem 1rem; display: flex; flex-wrap: wrap; gap: .4rem 1.2rem; align-items: baseline; }
nav .brand { font-weight: 700; color: var(--ink); text-decoration: none; font-size: 1.1rem; }
nav form.nav { margin: 0 0 0 auto; }
nav button.link { font: inherit; background: none; border: 0; padding: 0; color: var(--link); text-decoration: underline; cursor: pointer; }
main { max-width: 70rem; margin: 0 auto; padding: 1rem; }
h1 { font-size: 1.5rem; margin: .4rem 0 .2rem; overflow-wrap: anywhere; }
h2 { font-size: 1.2rem; margin: 1.6rem 0 .5rem; border-bottom: 1px solid var(--line); padding-bottom: .2rem; }
a { color: var(--link); }
.meta { color: var(--muted); margin: 0 0 .6rem; overflow-wrap: anywhere; }
.links { display: flex; flex-wrap: wrap; gap: .3rem 1rem; padding: 0; list-style: none; }
.scroll { overflow-x: auto; max-width: 100%; }
table { border-collapse: collapse; font-size: .95rem; }
th, td { text-align: left; padding: .25rem .7rem .25rem 0; border-bottom: 1px solid var(--line); vertical-align: top; }
td.num { font-variant-numeric: tabular-nums; white-space: nowrap; }
td.ptr, td.id { font-family: ui-monospace, "DejaVu Sans Mono", monospace; font-size: .88rem; }
td.id { overflow-wrap: anywhere; }
.warnings li { color: var(--warn); }
.plots { display: grid; grid-template-columns: repeat(auto-fill, minmax(min(100%, 44rem), 1fr)); gap: 1rem; }
figure { margin: 0; border: 1px solid var(--line); padding: .4rem; background: #fff; break-inside: avoid; max-width: 52rem; }
table.accuracy th { white-space: nowrap; }
figure img { width: 100%; height: auto; display: block; }
figcaption { font-size: .9rem; color: var(--muted); margin-top: .3rem; }
form.params { display: grid; gap: .9rem; max-width: 40rem; }
form.params label { display: block; font-weight: 600; }
form.params input { font: inherit; padding: .35rem .5rem; width: 100%; max-width: 20rem; border: 1px solid #999; border-radius: 3px; }
form.params .hint { color: var(--muted); font-size: .9rem; margin: .1rem 0 0; }
form.params .error, p.error { color: #a4000f; font-weight: 600; margin: .2rem 0 0; }
button { font: inherit; padding: .45rem 1.2rem; border: 1px solid var(--link); background: var(--link); color: #fff; border-radius: 3px; cursor: pointer; }
form.inline { display: flex; flex-wrap: wrap; gap: .5rem; align-items: center; margin: .5rem 0; }
form.inline input { font: inherit; width: 6rem; padding: .25rem .4rem; }
form.inline button { padding: .25rem .8rem; }
pre { background: var(--bg); border: 1px solid var(--line); padding: .6rem; overflow-x: auto; font-size: .85rem; }
footer { max-width: 70rem; margin: 2rem auto 1rem; padding: 0 1rem; color: var(--muted); font-size: .85rem; }
@media (max-width: 40rem) {
  table.accuracy th { white-space: normal; }
  td.num { white-space: normal; overflow-wrap: anywhere; }
}
@media print {
  header, footer, form.inline, .noprint { display: none; }
  main { max-width: none; padding: 0; }
  a { color: var(--ink); text-decoration: none; }
  .plots { display: block; }
  figure { margin-bottom: 1rem; }
}
"#;

/// Scripts: none; styles: this page's own; images and forms: this service.
const POLICY: &str = "default-src 'none'; img-src 'self' data:; style-src 'unsafe-inline'; form-action 'self'; base-uri 'none'; frame-ancestors 'none'";

/// A whole page around `body`, in the language of the request.
pub fn page(title: &str, body: Markup) -> Markup {
    let lang = i18n::current();
    html! {
        (DOCTYPE)
        html lang=(lang.tag()) {
            head {
                meta charset="utf-8";
                meta name="viewport" content="width=device-width, initial-scale=1";
                title { (title) " · mechdyn" }
                // No favicon request: the browser would ask for /favicon.ico.
                link rel="icon" href="data:,";
                style { (PreEscaped(CSS)) }
            }
            body {
                header { nav {
                    a.brand href="/" { "mechdyn" }
                    a href="/" { (tr(lang, "page-nav-home")) }
                    a href="/docs/" { (tr(lang, "page-nav-docs")) }
                    a href="/openapi.json" { (tr(lang, "page-nav-openapi")) }
                    @match crate::api::access::signed_in() {
                        Some(false) => a href="/signin" { (tr(lang, "page-signin-title")) },
                        Some(true) => form.nav method="post" action="/signout" {
                            button.link type="submit" { (tr(lang, "page-signout-button")) }
                        },
                        None => {},
                    }
                } }
                main { (body) }
                footer { (Msg::new("page-footer").arg("version", env!("CARGO_PKG_VERSION")).render(lang)) }
            }
        }
    }
}

/// The page as an HTML answer with `status`.
pub fn answer(status: StatusCode, page: Markup) -> Response {
    let mut response = (status, page.into_string()).into_response();
    let h = response.headers_mut();
    h.insert(header::CONTENT_TYPE, HeaderValue::from_static("text/html; charset=utf-8"));
    h.insert(header::CONTENT_SECURITY_POLICY, HeaderValue::from_static(POLICY));
    h.insert(header::X_CONTENT_TYPE_OPTIONS, HeaderValue::from_static("nosniff"));
    response
}

/// An error as a page: its status, its title and every message.
pub fn error(e: ApiError) -> Response {
    let status = e.status();
    let problem = e.problem();
    let details: Vec<String> = problem.errors.iter().map(FieldError::describe).collect();
    let mut response = answer(
        status,
        page(
            &problem.title,
            html! {
                h1 { (status.as_u16()) " " (problem.title) }
                p.error { (problem.detail) }
                @if !details.is_empty() { ul { @for d in &details { li { (d) } } } }
                p { a href="/" { (tr(i18n::current(), "page-back")) } }
            },
        ),
    );
    if status == StatusCode::UNAUTHORIZED {
        // RFC 9110 (15.5.2): a 401 says which scheme it wants.
        response.headers_mut().insert(header::WWW_AUTHENTICATE, HeaderValue::from_static("Bearer"));
    }
    response
}

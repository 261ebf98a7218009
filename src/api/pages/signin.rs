//! Signing in, for a browser, where the service has a token and keeps its
//! stored jobs to the token's holders ([`crate::api::access`]): a form that
//! takes the token once and sets the sign-in cookie, shown in place of a
//! job's page to a browser without it; and signing out.

use super::layout;
use crate::api::AppState;
use crate::api::access::{over_https, sign_out_cookie};
use crate::i18n::{self, tr};
use axum::extract::rejection::QueryRejection;
use axum::extract::{Query, State};
use axum::http::{HeaderMap, StatusCode, header};
use axum::response::{IntoResponse, Response};
use bytes::Bytes;
use maud::{Markup, html};
use serde::Deserialize;
use std::collections::HashMap;
use utoipa::ToSchema;

/// The sign-in form.
#[utoipa::path(get, path = "/signin", operation_id = "page_signin", tag = "pages",
    params(("next" = Option<String>, Query, description = "The page to go to once signed in (a path of this service; `/` by default)")),
    responses((status = 200, description = "The form", content_type = "text/html", body = String),
        (status = 400, description = "A query parameter given twice", content_type = "text/html", body = String)))]
pub async fn form(q: Result<Query<HashMap<String, String>>, QueryRejection>) -> Response {
    let next = q.ok().and_then(|Query(q)| q.get("next").cloned()).unwrap_or_default();
    layout::answer(StatusCode::OK, page(&next, false))
}

/// The sign-in form's fields.
#[derive(Deserialize, ToSchema)]
pub struct SignIn {
    /// The service's token (`--api-token`).
    token: String,
    /// The page to go on to: a path of this service (`/` by default, and for anything else).
    #[serde(default)]
    next: String,
}

/// Signs in: the token from the form, the cookie set, on to `next`.
#[utoipa::path(post, path = "/signin", operation_id = "signin", tag = "pages",
    request_body(content = SignIn, content_type = "application/x-www-form-urlencoded"),
    responses(
        (status = 303, description = "Signed in (or the service has no token): the cookie set (HttpOnly, SameSite=Strict), `Location` the page asked",
            headers(("Location" = String), ("Set-Cookie" = String))),
        (status = 400, description = "No `token` field: the form again", content_type = "text/html", body = String),
        (status = 401, description = "Not the service's token: the form again", content_type = "text/html", body = String)))]
pub async fn sign_in(State(state): State<AppState>, headers: HeaderMap, body: Bytes) -> Response {
    let Ok(SignIn { token, next }) = serde_urlencoded::from_bytes::<SignIn>(&body) else {
        return layout::answer(StatusCode::BAD_REQUEST, page("", true));
    };
    if !state.access.has_token() {
        return to(&next);
    }
    if !state.access.is_token(&token) {
        return layout::answer(StatusCode::UNAUTHORIZED, page(&next, true));
    }
    let next = next.as_str();
    let mut response = to(next);
    if let Some(cookie) = state.access.sign_in_cookie(over_https(&headers)) {
        response.headers_mut().insert(header::SET_COOKIE, cookie);
    }
    response
}

/// Signs out: the cookie cleared, on to the home page.
#[utoipa::path(post, path = "/signout", operation_id = "signout", tag = "pages",
    responses((status = 303, description = "Signed out: the cookie cleared", headers(("Location" = String), ("Set-Cookie" = String)))))]
pub async fn sign_out() -> Response {
    let mut response = to("/");
    response.headers_mut().insert(header::SET_COOKIE, sign_out_cookie());
    response
}

/// The 401 of a page of stored jobs: the form, to come back to `next`.
pub fn refused(next: &str) -> Response {
    let mut response = layout::answer(StatusCode::UNAUTHORIZED, page(next, false));
    response.headers_mut().insert(header::WWW_AUTHENTICATE, header::HeaderValue::from_static("Bearer"));
    response
}

/// The sign-in form as a section of a page (the home page shows it in place of the recent jobs).
pub fn section(next: &str, wrong: bool) -> Markup {
    let lang = i18n::current();
    let t = |id| tr(lang, id);
    html! {
        p { (t("page-signin-intro")) }
        @if wrong { p.error { (t("page-signin-wrong")) } }
        form.params method="post" action="/signin" {
            input type="hidden" name="next" value=(safe(next));
            div {
                label for="token" { (t("page-signin-token")) }
                input id="token" name="token" type="password" autocomplete="current-password" required;
            }
            div { button type="submit" { (t("page-signin-button")) } }
        }
    }
}

fn page(next: &str, wrong: bool) -> Markup {
    let title = tr(i18n::current(), "page-signin-title");
    layout::page(&title, html! { h1 { (title) } (section(next, wrong)) })
}

/// A 303 to `next`, where it is a path of this service.
fn to(next: &str) -> Response {
    (StatusCode::SEE_OTHER, [(header::LOCATION, safe(next).to_string())]).into_response()
}

/// `next` where it is a path of this service, else `/`: a sign-in never
/// sends a browser to another site.
fn safe(next: &str) -> &str {
    let local = next.starts_with('/') && !next.starts_with("//") && !next.contains(['\\', '\r', '\n']);
    if local { next } else { "/" }
}

#[cfg(test)]
mod tests {
    use super::safe;

    /// A sign-in goes on to a path of this service only.
    #[test]
    fn a_sign_in_never_leaves_the_service() {
        assert_eq!(safe("/jobs/x?step=3"), "/jobs/x?step=3");
        for elsewhere in ["https://evil.example/", "//evil.example/", "/\\evil.example", "", "jobs/x"] {
            assert_eq!(safe(elsewhere), "/", "{elsewhere}");
        }
    }
}

//! The database URL: which schemes this version serves, and the URL as it
//! may be shown (in logs and messages) without its password.

/// The database a URL names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Backend {
    /// `sqlite://path`, `sqlite:path`, `sqlite::memory:`: a file of this service's own.
    Sqlite,
    /// `postgres://` or `postgresql://`: a server several replicas may share.
    Postgres,
}

impl Backend {
    /// The scheme's name, as `/readyz` reports it.
    pub fn name(self) -> &'static str {
        match self {
            Self::Sqlite => "sqlite",
            Self::Postgres => "postgres",
        }
    }
}

/// A `DATABASE_URL` this version cannot use.
#[derive(Debug, thiserror::Error)]
#[error(
    "DATABASE_URL {url} has the scheme '{scheme}': mechdyn stores jobs in SQLite \
     (sqlite://data/mechdyn.db) or PostgreSQL (postgres://user:password@host:5432/mechdyn)"
)]
pub struct SchemeError {
    /// The URL, redacted.
    pub url: String,
    pub scheme: String,
}

/// The backend of a `sqlite:` or `postgres:` (`postgresql:`) URL.
pub fn check_scheme(url: &str) -> Result<Backend, SchemeError> {
    let scheme = url.split_once(':').map_or("", |(s, _)| s);
    match scheme.to_ascii_lowercase().as_str() {
        "sqlite" => Ok(Backend::Sqlite),
        "postgres" | "postgresql" => Ok(Backend::Postgres),
        _ => {
            let scheme = if scheme.is_empty() || scheme.contains('/') { "(none)" } else { scheme };
            Err(SchemeError { url: redact(url), scheme: scheme.into() })
        }
    }
}

/// The URL with any password replaced by `***`: `postgres://user:***@db/mechdyn`.
/// A `password=` query parameter is hidden too.
pub fn redact(url: &str) -> String {
    let mut out = url.to_string();
    if let Some(start) = out.find("://").map(|i| i + 3) {
        let authority_end = out[start..].find(['/', '?', '#']).map_or(out.len(), |i| start + i);
        if let Some(at) = out[start..authority_end].rfind('@').map(|i| start + i)
            && let Some(colon) = out[start..at].find(':').map(|i| start + i)
        {
            out.replace_range(colon + 1..at, "***");
        }
    }
    if let Some(q) = out.find('?') {
        let (head, query) = out.split_at(q + 1);
        let query: Vec<String> = query
            .split('&')
            .map(|kv| match kv.split_once('=') {
                Some((k, _)) if k.eq_ignore_ascii_case("password") => format!("{k}=***"),
                _ => kv.to_string(),
            })
            .collect();
        out = format!("{head}{}", query.join("&"));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn passwords_never_survive_redaction() {
        assert_eq!(redact("postgres://user:secret@db/mechdyn"), "postgres://user:***@db/mechdyn");
        assert_eq!(redact("postgres://user:p@ss@db:5432/m"), "postgres://user:***@db:5432/m");
        assert_eq!(redact("postgres://db/m?user=u&password=secret"), "postgres://db/m?user=u&password=***");
        assert_eq!(redact("sqlite://data/mechdyn.db"), "sqlite://data/mechdyn.db");
        assert_eq!(redact("postgres://user@db/m"), "postgres://user@db/m");
    }

    #[test]
    fn sqlite_and_postgres_urls_are_served() {
        assert_eq!(check_scheme("sqlite://data/mechdyn.db").unwrap(), Backend::Sqlite);
        assert_eq!(check_scheme("sqlite::memory:").unwrap(), Backend::Sqlite);
        assert_eq!(check_scheme("SQLITE://x.db").unwrap(), Backend::Sqlite);
        assert_eq!(check_scheme("postgres://user:secret@db/mechdyn").unwrap(), Backend::Postgres);
        assert_eq!(check_scheme("postgresql://db/mechdyn").unwrap(), Backend::Postgres);
        let e = check_scheme("mysql://user:secret@db/mechdyn").unwrap_err();
        assert_eq!(e.scheme, "mysql");
        assert!(!e.to_string().contains("secret"), "{e}");
        assert_eq!(check_scheme("data/mechdyn.db").unwrap_err().scheme, "(none)");
    }
}

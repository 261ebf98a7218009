//! Every text a person reads, from one message catalogue per language
//! (Fluent: `i18n/en/*.ftl`, `i18n/es/*.ftl` — the service's own words,
//! the kinds' requests, the results' warnings and methods), so that a
//! message written once has its Spanish beside it and a test fails when it
//! has not.
//!
//! A message is named by its id and carries its arguments ([`Msg`]); it is
//! rendered in a language when it is answered. The language of an answer is
//! negotiated once per request ([`Lang::negotiate`]: `?lang=`, then
//! `Accept-Language`; English by default) and held for the request's task
//! ([`within`], [`current`]), so that an error, a page or a plot rendered
//! anywhere below a handler speaks the asker's language without every
//! function being handed it. Outside a request (the command line, the
//! engine's tests) it is English.
//!
//! The course's own words (seed 000): par, reacción, volante, par motor,
//! grado de irregularidad, energía cinética, leva, seguidor.

pub mod names;
mod stored;

use fluent_bundle::concurrent::FluentBundle;
use fluent_bundle::{FluentArgs, FluentResource};
use std::borrow::Cow;
use std::sync::LazyLock;

pub use stored::MessageDoc;

/// A language the service answers in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Lang {
    #[default]
    En,
    Es,
}

impl Lang {
    pub const ALL: [Lang; 2] = [Lang::En, Lang::Es];

    /// The BCP 47 tag (`Content-Language`, `<html lang>`).
    pub fn tag(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Es => "es",
        }
    }

    /// The language of a tag (`es-ES` is Spanish), where the service speaks it.
    pub fn of(tag: &str) -> Option<Lang> {
        let primary = tag.trim().split(['-', '_']).next().unwrap_or("").to_ascii_lowercase();
        Lang::ALL.into_iter().find(|l| l.tag() == primary)
    }

    /// The language of a request: `?lang=` when it names one the service
    /// has, else the first of `Accept-Language` by its weights that it has,
    /// else English. A preference the service cannot meet is not an error.
    pub fn negotiate(query: Option<&str>, accept: Option<&str>) -> Lang {
        if let Some(lang) = query.and_then(Lang::of) {
            return lang;
        }
        let mut best: Option<(f32, Lang)> = None;
        for item in accept.unwrap_or("").split(',') {
            let mut parts = item.split(';');
            let Some(lang) = parts.next().and_then(Lang::of) else { continue };
            let q = parts
                .find_map(|p| p.trim().strip_prefix("q=").and_then(|q| q.trim().parse::<f32>().ok()))
                .unwrap_or(1.0);
            if q > 0.0 && best.is_none_or(|(b, _)| q > b) {
                best = Some((q, lang));
            }
        }
        best.map_or(Lang::En, |(_, l)| l)
    }

    /// A number as this language writes it in a sentence: shortest
    /// round-trip digits (powers of ten from 10⁹ and below 10⁻⁴), with a
    /// decimal comma in Spanish.
    pub fn number(self, x: f64) -> String {
        let plain = x == 0.0 || !x.is_finite() || (1e-4..1e9).contains(&x.abs());
        self.decimal(if plain { format!("{x}") } else { format!("{x:e}") })
    }

    /// `x` to four significant figures, for a label or a page (powers of
    /// ten beyond 10⁶ and below 10⁻³), with a decimal comma in Spanish.
    pub fn figures(self, x: f64) -> String {
        if x == 0.0 || !x.is_finite() {
            return format!("{x}");
        }
        let magnitude = x.abs().log10().floor();
        if !(-3.0..6.0).contains(&magnitude) {
            return self.decimal(format!("{x:.3e}"));
        }
        let decimals = (3.0 - magnitude).max(0.0) as usize;
        let text = format!("{x:.decimals$}");
        // 0.04, not 0.04000: the zeros a rounding leaves say nothing.
        let text = if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.').to_string() } else { text };
        self.decimal(text)
    }

    /// A number written with a decimal point, as this language writes it.
    pub fn decimal(self, text: String) -> String {
        if self == Lang::Es { text.replacen('.', ",", 1) } else { text }
    }
}

/// One argument of a message.
#[derive(Clone, Debug, PartialEq)]
enum Arg {
    Text(String),
    Number(f64),
    Figures(f64),
    Written(String),
    Count(usize),
    Said(Box<Msg>),
    List(Vec<Msg>),
}

/// A message of the catalogue with its arguments, rendered in a language
/// when it is answered. A result stores the messages its texts were written
/// from (`stored.rs`), so its id and argument names may be owned.
#[derive(Clone, Debug, PartialEq)]
pub struct Msg {
    id: Cow<'static, str>,
    args: Vec<(Cow<'static, str>, Arg)>,
}

impl Msg {
    pub fn new(id: &'static str) -> Self {
        Self { id: Cow::Borrowed(id), args: Vec::new() }
    }

    /// The message's id in the catalogue.
    pub fn id(&self) -> &str {
        &self.id
    }

    /// A text argument (a name, a unit, a value as the client wrote it).
    pub fn arg(mut self, name: &'static str, value: impl std::fmt::Display) -> Self {
        self.args.push((Cow::Borrowed(name), Arg::Text(value.to_string())));
        self
    }

    /// A number argument, written as the language writes numbers.
    pub fn num(mut self, name: &'static str, value: f64) -> Self {
        self.args.push((Cow::Borrowed(name), Arg::Number(value)));
        self
    }

    /// A measured value to four significant figures (a warning's angle, a
    /// residual), as the language writes numbers.
    pub fn fig(mut self, name: &'static str, value: f64) -> Self {
        self.args.push((Cow::Borrowed(name), Arg::Figures(value)));
        self
    }

    /// A number already written with a decimal point in the caller's
    /// format (`1.000000e-3`), its decimal mark the language's.
    pub fn written(mut self, name: &'static str, text: String) -> Self {
        self.args.push((Cow::Borrowed(name), Arg::Written(text)));
        self
    }

    /// A count, for the catalogue's plural forms (`1 campo`, `2 campos`).
    pub fn count(mut self, name: &'static str, n: usize) -> Self {
        self.args.push((Cow::Borrowed(name), Arg::Count(n)));
        self
    }

    /// A message within this one, rendered in the same language.
    pub fn with(mut self, name: &'static str, inner: Msg) -> Self {
        self.args.push((Cow::Borrowed(name), Arg::Said(Box::new(inner))));
        self
    }

    /// Messages within this one, rendered in the same language one after
    /// the other, separated by commas (`0,1 rad, 0,5 rad a 0,7 rad`).
    pub fn list(mut self, name: &'static str, items: Vec<Msg>) -> Self {
        self.args.push((Cow::Borrowed(name), Arg::List(items)));
        self
    }

    /// The message in `lang`; a message missing from the catalogue (a test
    /// forbids it) renders as its id.
    pub fn render(&self, lang: Lang) -> String {
        let bundle = &CATALOGUES[lang as usize];
        let Some(pattern) = bundle.get_message(&self.id).and_then(|m| m.value()) else {
            return self.id.to_string();
        };
        let mut args = FluentArgs::new();
        for (name, value) in &self.args {
            match value {
                Arg::Text(t) => args.set(name.clone(), t.as_str()),
                Arg::Number(x) => args.set(name.clone(), lang.number(*x)),
                Arg::Figures(x) => args.set(name.clone(), lang.figures(*x)),
                Arg::Written(text) => args.set(name.clone(), lang.decimal(text.clone())),
                Arg::Count(n) => args.set(name.clone(), *n),
                Arg::Said(inner) => args.set(name.clone(), inner.render(lang)),
                Arg::List(items) => {
                    args.set(name.clone(), items.iter().map(|m| m.render(lang)).collect::<Vec<_>>().join(", "))
                }
            }
        }
        let mut errors = Vec::new();
        bundle.format_pattern(pattern, Some(&args), &mut errors).into_owned()
    }

    /// The message in the language of the request being answered.
    pub fn text(&self) -> String {
        self.render(current())
    }
}

/// A message without arguments in the language of the request being answered.
pub fn say(id: &'static str) -> String {
    Msg::new(id).text()
}

/// A message without arguments in `lang`.
pub fn tr(lang: Lang, id: &'static str) -> String {
    Msg::new(id).render(lang)
}

/// The catalogue's message `id` without arguments in `lang`, for an id
/// made at run time (a result's field named in words); None where the
/// catalogue has none.
pub fn tr_named(lang: Lang, id: &str) -> Option<String> {
    let bundle = &CATALOGUES[lang as usize];
    let pattern = bundle.get_message(id).and_then(|m| m.value())?;
    Some(bundle.format_pattern(pattern, None, &mut Vec::new()).into_owned())
}

/// Each language's catalogue, in files by what they speak of.
const SOURCES: [[&str; 3]; 2] = [
    [include_str!("i18n/en/service.ftl"), include_str!("i18n/en/requests.ftl"), include_str!("i18n/en/results.ftl")],
    [include_str!("i18n/es/service.ftl"), include_str!("i18n/es/requests.ftl"), include_str!("i18n/es/results.ftl")],
];

static CATALOGUES: LazyLock<[FluentBundle<FluentResource>; 2]> = LazyLock::new(|| Lang::ALL.map(catalogue));

fn catalogue(lang: Lang) -> FluentBundle<FluentResource> {
    let id = lang.tag().parse().unwrap_or_default();
    let mut bundle = FluentBundle::new_concurrent(vec![id]);
    // Plain text: no Unicode isolation marks around arguments.
    bundle.set_use_isolating(false);
    for source in SOURCES[lang as usize] {
        // A syntax error or an id twice is caught by the tests; what parsed is used.
        let resource = FluentResource::try_new(source.to_string()).unwrap_or_else(|(r, _)| r);
        let _ = bundle.add_resource(resource);
    }
    bundle
}

tokio::task_local! {
    static LANG: Lang;
}

/// The language of the request being answered (English outside one).
pub fn current() -> Lang {
    LANG.try_with(|l| *l).unwrap_or_default()
}

/// Runs `f` answering in `lang`.
pub async fn within<F: std::future::Future>(lang: Lang, f: F) -> F::Output {
    LANG.scope(lang, f).await
}

/// Runs `f` (on a blocking thread, say) in `lang`.
pub fn within_sync<R>(lang: Lang, f: impl FnOnce() -> R) -> R {
    LANG.sync_scope(lang, f)
}

#[cfg(test)]
mod tests;

//! The catalogues agree: each parses, each message of one is in the other
//! with the same arguments, and every message the code names is in both.

use super::*;
use std::collections::{BTreeMap, BTreeSet};

/// Each message's id and the arguments (`$name`) its text uses.
fn messages(source: &str) -> BTreeMap<String, BTreeSet<String>> {
    let mut out: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut id = String::new();
    for line in source.lines() {
        if line.starts_with('#') || line.trim().is_empty() {
            continue;
        }
        if !line.starts_with(' ')
            && let Some((name, _)) = line.split_once(" =")
        {
            id = name.trim().to_string();
            out.entry(id.clone()).or_default();
        }
        let vars = line.split('$').skip(1).map(|v| v.chars().take_while(|c| c.is_alphanumeric() || *c == '_'));
        out.entry(id.clone()).or_default().extend(vars.map(String::from_iter));
    }
    out
}

/// A language's catalogue: its files one after the other.
fn catalogue_text(lang: Lang) -> String {
    SOURCES[lang as usize].join("\n")
}

#[test]
fn both_catalogues_parse_and_name_each_message_once() {
    for lang in Lang::ALL {
        let mut seen = BTreeSet::new();
        for source in SOURCES[lang as usize] {
            if let Err((_, errors)) = FluentResource::try_new(source.to_string()) {
                panic!("{}: {errors:?}", lang.tag());
            }
            let twice: Vec<String> = messages(source).into_keys().filter(|id| !seen.insert(id.clone())).collect();
            assert!(twice.is_empty(), "{}: named twice: {twice:?}", lang.tag());
        }
    }
}

/// A message without its Spanish (or English), or whose arguments differ
/// between the two, fails here.
#[test]
fn every_message_has_both_languages_with_the_same_arguments() {
    let (en, es) = (messages(&catalogue_text(Lang::En)), messages(&catalogue_text(Lang::Es)));
    let missing: Vec<&String> = en.keys().filter(|k| !es.contains_key(*k)).collect();
    assert!(missing.is_empty(), "without Spanish: {missing:?}");
    let missing: Vec<&String> = es.keys().filter(|k| !en.contains_key(*k)).collect();
    assert!(missing.is_empty(), "without English: {missing:?}");
    for (id, args) in &en {
        assert_eq!(args, &es[id], "{id}: its arguments in English and Spanish");
    }
    assert!(en.len() > 50, "the catalogue is read: {} messages", en.len());
}

/// Every id written in the code — a string literal `"group-rest"` whose
/// group is one of the catalogue's (`detail`, `unit`, `page`…) — is in the
/// catalogue.
#[test]
fn every_message_the_code_names_is_in_the_catalogue() {
    let en = messages(&catalogue_text(Lang::En));
    let groups: BTreeSet<&str> = en.keys().filter_map(|id| id.split('-').next()).collect();
    let mut named = BTreeSet::new();
    let mut dirs = vec![std::path::PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/src"))];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap().flatten() {
            let path = entry.path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") && !path.ends_with("i18n/tests.rs") {
                let text = std::fs::read_to_string(&path).unwrap();
                let ids = text.split('"').skip(1).step_by(2).filter(|s| is_id(s, &groups));
                named.extend(ids.map(|id| (id.to_string(), path.display().to_string())));
            }
        }
    }
    let unknown: Vec<_> = named.iter().filter(|(id, _)| !en.contains_key(id)).collect();
    assert!(unknown.is_empty(), "named in the code, not in the catalogue: {unknown:?}");
    assert!(named.len() > 50, "the code is read: {} ids", named.len());
}

/// `text` looks like a message id of one of the catalogue's groups.
fn is_id(text: &str, groups: &BTreeSet<&str>) -> bool {
    let words = text.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-');
    words && text.contains('-') && text.split('-').next().is_some_and(|g| groups.contains(g))
}

#[test]
fn the_language_of_a_request() {
    assert_eq!(Lang::negotiate(None, None), Lang::En);
    assert_eq!(Lang::negotiate(None, Some("es-ES,es;q=0.9,en;q=0.8")), Lang::Es);
    assert_eq!(Lang::negotiate(None, Some("en-GB,es;q=0.5")), Lang::En);
    assert_eq!(Lang::negotiate(None, Some("fr, es;q=0.3")), Lang::Es);
    assert_eq!(Lang::negotiate(None, Some("de, fr")), Lang::En);
    assert_eq!(Lang::negotiate(None, Some("es;q=0")), Lang::En);
    assert_eq!(Lang::negotiate(Some("es"), Some("en")), Lang::Es);
    assert_eq!(Lang::negotiate(Some("ES-es"), None), Lang::Es);
    assert_eq!(Lang::negotiate(Some("fr"), Some("es")), Lang::Es, "an unmet ?lang= leaves the header");
}

#[test]
fn messages_render_with_their_arguments_and_numbers() {
    let m = Msg::new("parameter-below").arg("text", "-3").num("min", 0.5).arg("unit", " N*m");
    assert_eq!(m.render(Lang::En), "-3 is below the least value, 0.5 N*m");
    assert_eq!(m.render(Lang::Es), "-3 está por debajo del valor mínimo, 0,5 N*m");
    assert_eq!(Msg::new("detail-invalid").count("count", 1).render(Lang::Es), "1 campo no válido");
    assert_eq!(Msg::new("detail-invalid").count("count", 3).render(Lang::En), "3 invalid fields");
    assert_eq!(
        Msg::new("field-expression").arg("text", "20*t").render(Lang::En),
        "'20*t' is an expression, not a quantity: write it as {\"expr\": \"20*t\"}"
    );
    assert_eq!(Msg::new("no-such-message").render(Lang::Es), "no-such-message");
    // Four significant figures, the zeros of the rounding left out.
    assert_eq!(Lang::En.figures(353.521427), "353.5");
    assert_eq!(Lang::Es.figures(353.521427), "353,5");
    assert_eq!(Lang::Es.figures(0.04), "0,04");
    assert_eq!(Lang::En.figures(1500.0), "1500");
    assert_eq!(Lang::Es.figures(2.706e-11), "2,706e-11");
}

//! Numbers and units as people write them: a decimal comma (`0,02`, the
//! Spanish lab's way) read wherever a number is text — query parameters,
//! quantity strings, form fields, CSV cells — and, for a unit that is not
//! known, the known one it is probably meant to be (`kgm2` → `kg*m^2`).
//!
//! One reader for every place: [`number`] here, and
//! [`super::parse_quantity`] through [`number_length`].

use super::{UNITS, table_unit};

/// A number written with a decimal point or a decimal comma (`0.02`,
/// `0,02`, `-1,5e3`): one comma and no point is the decimal comma; a
/// thousands separator is not a decimal (`1.000,5` and `1,000.5` are not
/// numbers). None for anything else; the value may be infinite (`inf`),
/// which callers refuse as they see fit.
pub fn number(text: &str) -> Option<f64> {
    let t = text.trim();
    match t.matches(',').count() {
        0 => t.parse().ok(),
        1 if !t.contains('.') => t.replacen(',', ".", 1).parse().ok(),
        _ => None,
    }
}

/// `text` without its thousands separators, where it is a number written
/// with them ("1.200,5" → "1200,5", "1,200.5" → "1200.5", "1.200.000" →
/// "1200000"): groups of three digits after the first, apart by one mark,
/// the other mark (once, last) the decimal one. None for anything else.
pub fn ungrouped(text: &str) -> Option<String> {
    let t = text.trim();
    let (sign, t) = t.strip_prefix(['-', '+']).map_or(("", t), |rest| (&text.trim()[..1], rest));
    let marks: Vec<char> = t.chars().filter(|c| *c == '.' || *c == ',').collect();
    let (&last, _) = marks.split_last()?;
    let group = if marks.iter().all(|m| *m == last) && marks.len() >= 2 { last } else { *marks.first()? };
    let (whole, decimals) = match t.rfind(|c| c != group && (c == '.' || c == ',')) {
        Some(i) => (&t[..i], Some(&t[i..])),
        None => (t, None),
    };
    let parts: Vec<&str> = whole.split(group).collect();
    let digits = |p: &str| !p.is_empty() && p.chars().all(|c| c.is_ascii_digit());
    let grouped = parts.len() >= 2
        && digits(parts[0])
        && parts[0].len() <= 3
        && parts[1..].iter().all(|p| p.len() == 3 && digits(p))
        && decimals.is_none_or(|d| d.len() > 1 && digits(&d[1..]));
    grouped.then(|| format!("{sign}{}{}", parts.concat(), decimals.unwrap_or("")))
}

/// Length (bytes) of the number at the start of `t`: sign, digits, a
/// decimal point or comma followed by digits, exponent.
pub fn number_length(t: &str) -> usize {
    let b = t.as_bytes();
    let digits = |mut i: usize| {
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
        i
    };
    let mut i = if b.first().is_some_and(|c| *c == b'+' || *c == b'-') { 1 } else { 0 };
    i = digits(i);
    match b.get(i) {
        Some(b'.') => i = digits(i + 1),
        // A comma is a decimal one only with a digit after it.
        Some(b',') if b.get(i + 1).is_some_and(u8::is_ascii_digit) => i = digits(i + 1),
        _ => {}
    }
    // An exponent only when digits follow it (`2e3`, not the `e` of a unit).
    if b.get(i).is_some_and(|c| *c == b'e' || *c == b'E') {
        let mut j = i + 1;
        if b.get(j).is_some_and(|c| *c == b'+' || *c == b'-') {
            j += 1;
        }
        if b.get(j).is_some_and(u8::is_ascii_digit) {
            i = digits(j);
        }
    }
    i
}

/// A unit as a person writes it, in the table's notation: superscript
/// powers (`m²`, `s⁻¹`) with a caret, `×` and a dot between names
/// (`kg.m`) as `*`, a space between names (`kg m^2`) as a product, and a
/// unit abbreviated a letter at a time (`r.p.m.`) as its letters.
pub fn normalized(text: &str) -> String {
    if let Some(letters) = abbreviated(text.trim()) {
        return letters;
    }
    let t =
        text.trim().replace('²', "^2").replace('³', "^3").replace("⁻¹", "^-1").replace("⁻²", "^-2").replace('×', "*");
    let chars: Vec<char> = t.chars().collect();
    let operator = |c: char| "*/·^".contains(c);
    let mut out = String::with_capacity(t.len());
    for (i, &c) in chars.iter().enumerate() {
        let next = chars[i + 1..].iter().copied().find(|c| !c.is_whitespace());
        let prev = out.chars().last();
        let between_names = prev.is_some_and(|p: char| !operator(p)) && next.is_some_and(|n| !operator(n));
        match c {
            c if c.is_whitespace() => {
                if between_names && prev != Some('*') {
                    out.push('*');
                }
            }
            '.' if prev.is_some_and(char::is_alphabetic) && next.is_some_and(char::is_alphabetic) => out.push('*'),
            c => out.push(c),
        }
    }
    out
}

/// A unit abbreviated a letter at a time, each followed by a point
/// (`r.p.m.`), or all but the last where three letters or more make a
/// unit of the table (`r.p.m`): its letters (`rpm`). Otherwise a point
/// between names is a product (`kg.m`, `N.m`; `m.s` is not `ms`).
fn abbreviated(text: &str) -> Option<String> {
    let chars: Vec<char> = text.chars().collect();
    let last_dotted = chars.last() == Some(&'.');
    let dotted =
        chars.len() >= 3 && chars.chunks(2).all(|p| p[0].is_ascii_alphabetic() && p.get(1).is_none_or(|c| *c == '.'));
    let letters: String = chars.iter().step_by(2).collect();
    let known = letters.len() >= 3 && super::table_unit(&letters).is_some();
    (dotted && (last_dotted || known)).then_some(letters)
}

/// The known unit that an unknown `name` probably means, written as the
/// service reads it: a power without `^` (`m2` → `m^2`), two units run
/// together (`kgm` → `kg*m`, `Nmm` → `N*mm`), a plural (`lbs` → `lb`), one
/// letter off (`rmp` → `rpm`), or a Spanish word (`seg` → `s`, `grados` →
/// `deg`, `vueltas` → `rev`).
pub fn suggestion(name: &str) -> Option<String> {
    let name = name.trim();
    if name.is_empty() {
        return None;
    }
    let words = [
        ("seg", "s"),
        ("segundo", "s"),
        ("segundos", "s"),
        ("grado", "deg"),
        ("grados", "deg"),
        ("vuelta", "rev"),
        ("vueltas", "rev"),
    ];
    if let Some((_, unit)) = words.iter().find(|(w, _)| w.eq_ignore_ascii_case(name)) {
        return Some((*unit).to_string());
    }
    let stem = name.trim_end_matches(|c: char| c.is_ascii_digit());
    let power = &name[stem.len()..];
    let powered = |base: String| if power.is_empty() { base } else { format!("{base}^{power}") };
    if !power.is_empty() && power.len() <= 1 && table_unit(stem).is_some() {
        return Some(powered(stem.to_string()));
    }
    let plural = name.strip_suffix('s').filter(|s| s.len() >= 2 && table_unit(s).is_some());
    if let Some(one) = plural {
        return Some(one.to_string());
    }
    if let Some(pair) = run_together(stem) {
        return Some(powered(pair));
    }
    (power.is_empty()).then(|| one_letter_off(name)).flatten()
}

/// `ab` read as two table units `a*b` (the first split that works).
fn run_together(name: &str) -> Option<String> {
    (1..name.len()).filter(|&i| name.is_char_boundary(i)).find_map(|i| {
        let (a, b) = name.split_at(i);
        (table_unit(a).is_some() && table_unit(b).is_some()).then(|| format!("{a}*{b}"))
    })
}

/// The only table unit one edit (a letter changed, added, left out, or two
/// swapped) from `name`, for names of two letters or more.
fn one_letter_off(name: &str) -> Option<String> {
    if name.chars().count() < 2 {
        return None;
    }
    let mut near = UNITS.iter().map(|u| u.0).filter(|u| u.len() >= 2 && edits_le_one(name, u));
    let found = near.next()?;
    near.next().is_none().then(|| found.to_string())
}

/// Whether `a` and `b` are at most one edit apart (Damerau: a swap of two
/// neighbouring letters is one edit).
fn edits_le_one(a: &str, b: &str) -> bool {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let common = a.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let (ra, rb) = (&a[common..], &b[common..]);
    match (ra.len(), rb.len()) {
        (0, 0) => true,
        (x, y) if x == y => ra[1..] == rb[1..] || (x >= 2 && ra[0] == rb[1] && ra[1] == rb[0] && ra[2..] == rb[2..]),
        (x, y) if x == y + 1 => ra[1..] == *rb,
        (x, y) if y == x + 1 => *ra == rb[1..],
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::ungrouped;

    #[test]
    fn a_number_with_thousands_separators_is_recognised() {
        assert_eq!(ungrouped("1.200,5").as_deref(), Some("1200,5"));
        assert_eq!(ungrouped("1,200.5").as_deref(), Some("1200.5"));
        assert_eq!(ungrouped("-1.200.000").as_deref(), Some("-1200000"));
        for not in ["1.2.3", "12,3,4", "1.20,5", "abc", "1,5", "1.200,"] {
            assert_eq!(ungrouped(not), None, "{not}");
        }
    }

    use super::*;

    /// Decimal points and commas read the same; thousands separators and
    /// two commas are not numbers.
    #[test]
    fn decimal_commas_and_points() {
        for (text, x) in [("0,02", 0.02), ("0.02", 0.02), ("-1,5e3", -1500.0), (" 353,5 ", 353.5), (",5", 0.5)] {
            assert_eq!(number(text), Some(x), "{text}");
        }
        for text in ["1.000,5", "1,000.5", "1,2,3", "", "abc", "1, 5"] {
            assert_eq!(number(text), None, "{text}");
        }
        assert_eq!(number_length("0,02 m"), 4);
        assert_eq!(number_length("3,m"), 1);
        assert_eq!(number_length("1,5e-3kg"), 6);
    }

    #[test]
    fn units_as_a_person_writes_them() {
        for (written, as_table) in [
            ("kg·m²", "kg·m^2"),
            ("kg*m²", "kg*m^2"),
            ("kg m^2", "kg*m^2"),
            ("kg  m ^2", "kg*m^2"),
            ("kg.m2", "kg*m2"),
            ("N × m", "N*m"),
            ("s⁻¹", "s^-1"),
            ("rad / s", "rad/s"),
            ("r.p.m.", "rpm"),
            ("R.P.M.", "RPM"),
            ("r.p.m", "rpm"),
            ("N.m", "N*m"),
            ("m.s", "m*s"),
        ] {
            assert_eq!(normalized(written), as_table, "{written}");
        }
        for written in ["kg·m²", "kg*m²", "kg m^2", "kg.m2", "kg m2"] {
            assert_eq!(crate::units::parse_unit(written), crate::units::parse_unit("kg*m^2"), "{written}");
        }
        for written in ["r.p.m.", "R.P.M.", "r.p.m", "rpm"] {
            assert_eq!(crate::units::parse_unit(written), crate::units::parse_unit("rev/min"), "{written}");
        }
    }

    #[test]
    fn suggestions_for_units_written_otherwise() {
        for (name, meant) in [
            ("m2", "m^2"),
            ("kgm2", "kg*m^2"),
            ("kgm", "kg*m"),
            ("Nmm", "N*mm"),
            ("rmp", "rpm"),
            ("lbs", "lb"),
            ("degs", "deg"),
            ("seg", "s"),
            ("Grados", "deg"),
            ("vueltas", "rev"),
            ("lbfft", "lbf*ft"),
        ] {
            assert_eq!(suggestion(name).as_deref(), Some(meant), "{name}");
        }
        for name in ["furlong", "", "x", "qq2"] {
            assert_eq!(suggestion(name), None, "{name}");
        }
    }
}

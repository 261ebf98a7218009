//! Results stored compressed: a result of at least [`MIN`] bytes is kept
//! zstd-compressed (level [`LEVEL`]) in `result_zstd`, its `result` text
//! left empty; read back byte for byte. A swept mechanism's answer is a few
//! hundred kilobytes of numbers that compress 4.7-fold (K1 over 360 steps:
//! 601 KB to 127 KB): the database and its backups hold a class's jobs in
//! a fifth of the bytes, for ~2 ms of compression per such job on the
//! request's own task (~340 MB/s) and ~0.6 ms to read it back. Smaller
//! results stay text (compression would buy little and cost a frame each).

use super::StoreError;
use bytes::Bytes;

/// Results shorter than this are stored as text.
pub const MIN: usize = 4096;
/// zstd's fastest standard level; its negative ("fast") levels compress
/// K1's answer 2.4–2.6× only, levels 2 and 3 no smaller and slower.
const LEVEL: i32 = 1;

/// A result as stored: its text, or empty text and its compressed bytes.
pub struct Packed<'a> {
    pub text: &'a str,
    pub zstd: Option<Vec<u8>>,
}

/// `result` (UTF-8 JSON text) as it is to be stored.
pub fn pack(result: &Bytes) -> Packed<'_> {
    let text = std::str::from_utf8(result).unwrap_or("null");
    if text.len() < MIN {
        return Packed { text, zstd: None };
    }
    match zstd::bulk::compress(text.as_bytes(), LEVEL) {
        Ok(z) if z.len() < text.len() => Packed { text: "", zstd: Some(z) },
        _ => Packed { text, zstd: None },
    }
}

/// The result a row holds: its text, or its compressed bytes expanded.
pub fn unpack(text: String, zstd: Option<Vec<u8>>) -> Result<Bytes, StoreError> {
    let Some(z) = zstd else { return Ok(text.into()) };
    let unreadable = |why: String| StoreError::Unavailable(format!("a stored result cannot be read: {why}"));
    let bytes = zstd::decode_all(z.as_slice()).map_err(|e| unreadable(e.to_string()))?;
    std::str::from_utf8(&bytes).map_err(|e| unreadable(e.to_string()))?;
    Ok(bytes.into())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Short text stays text; a long result comes back byte for byte from
    /// fewer bytes; damaged bytes are an error, not a result.
    #[test]
    fn a_result_comes_back_as_it_went_in() {
        let short = Bytes::from_static(b"{\"a\":1}");
        let p = pack(&short);
        assert!(p.zstd.is_none() && p.text == "{\"a\":1}");
        let long: String =
            (0..2000).map(|k| format!("{{\"x\":{},\"y\":{}}},", k as f64 * 0.1, (k as f64).sin())).collect();
        let long = Bytes::from(format!("[{}0]", long));
        let p = pack(&long);
        let z = p.zstd.expect("compressed");
        assert!(p.text.is_empty() && z.len() < long.len() / 2, "{} of {}", z.len(), long.len());
        assert_eq!(unpack(String::new(), Some(z.clone())).unwrap(), long);
        let mut bad = z;
        bad.truncate(bad.len() / 2);
        assert!(unpack(String::new(), Some(bad)).is_err());
    }
}

//! A strict reading of a parsed JSON body: serde's derived structs also take
//! a JSON array (`[60, 0.04]` for a request, its fields by position), which
//! the schema forbids and which hides a client's mistake behind jargon
//! ("expected struct FlywheelRequest with 13 elements"). [`Strict`] reads
//! a `serde_json::Value` as serde_json does, except that a struct must be a
//! JSON object; and a number may come as a text a person wrote (`"0,1"`).
//! It is a deserializer of its own (not a pre-pass) because only the types
//! being read know where a struct (or a number) is expected.

use serde::de::value::StrDeserializer;
use serde::de::{self, DeserializeSeed, Deserializer, IntoDeserializer, Unexpected, Visitor};
use serde_json::{Map, Value};

type Error = serde_json::Error;

/// A JSON value read strictly.
pub struct Strict<'de>(pub &'de Value);

thread_local! {
    /// Each object read as a struct (its address in the value read) and the
    /// struct's fields: what an unknown field's neighbours are called.
    static FIELDS: std::cell::RefCell<Vec<(usize, &'static [&'static str])>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// The fields of the struct each object of `value` was read as, over
/// `read` (which reads `value` with [`Strict`] on this thread): an object
/// is known by its address in `value`.
pub fn fields_read<T>(value: &Value, read: impl FnOnce(&Value) -> T) -> (T, Vec<(usize, &'static [&'static str])>) {
    FIELDS.with_borrow_mut(Vec::clear);
    let out = read(value);
    (out, FIELDS.with_borrow_mut(std::mem::take))
}

/// The elements of an array, each read strictly.
struct Seq<'de>(std::slice::Iter<'de, Value>);

/// The members of an object, each value read strictly.
struct Members<'de> {
    iter: serde_json::map::Iter<'de>,
    value: Option<&'de Value>,
}

impl<'de> Members<'de> {
    fn new(map: &'de Map<String, Value>) -> Self {
        Self { iter: map.iter(), value: None }
    }
}

fn unexpected(v: &Value) -> Unexpected<'_> {
    match v {
        Value::Null => Unexpected::Unit,
        Value::Bool(b) => Unexpected::Bool(*b),
        Value::Number(n) => n.as_f64().map_or(Unexpected::Other("number"), Unexpected::Float),
        Value::String(s) => Unexpected::Str(s),
        Value::Array(_) => Unexpected::Seq,
        Value::Object(_) => Unexpected::Map,
    }
}

impl<'de> Deserializer<'de> for Strict<'de> {
    type Error = Error;

    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Error> {
        match self.0 {
            Value::Null => visitor.visit_unit(),
            Value::Bool(b) => visitor.visit_bool(*b),
            Value::Number(n) => match (n.as_u64(), n.as_i64(), n.as_f64()) {
                (Some(u), _, _) => visitor.visit_u64(u),
                (_, Some(i), _) => visitor.visit_i64(i),
                (_, _, Some(f)) => visitor.visit_f64(f),
                _ => Err(de::Error::custom("a number out of range")),
            },
            Value::String(s) => visitor.visit_borrowed_str(s),
            Value::Array(a) => {
                // As serde_json does: an array longer than what was read (four numbers
                // for [x, y, z]) is an error, not its first items.
                let mut seq = Seq(a.iter());
                let value = visitor.visit_seq(&mut seq)?;
                match seq.0.len() {
                    0 => Ok(value),
                    _ => Err(de::Error::invalid_length(a.len(), &"json-expect-fewer")),
                }
            }
            Value::Object(m) => visitor.visit_map(Members::new(m)),
        }
    }

    fn deserialize_option<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Error> {
        match self.0 {
            Value::Null => visitor.visit_none(),
            _ => visitor.visit_some(self),
        }
    }

    fn deserialize_newtype_struct<V: Visitor<'de>>(self, _: &'static str, visitor: V) -> Result<V::Value, Error> {
        visitor.visit_newtype_struct(self)
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _: &'static str,
        fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, Error> {
        match self.0 {
            Value::Object(m) => {
                FIELDS.with_borrow_mut(|known| known.push((self.0 as *const Value as usize, fields)));
                visitor.visit_map(Members::new(m))
            }
            other => Err(de::Error::invalid_type(unexpected(other), &"an object")),
        }
    }

    fn deserialize_enum<V: Visitor<'de>>(
        self,
        _: &'static str,
        _: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, Error> {
        match self.0 {
            Value::String(s) => visitor.visit_enum(StrDeserializer::<Error>::new(s)),
            // An externally tagged variant with data: {"name": value}.
            Value::Object(m) if m.len() == 1 => {
                let (key, value) = m.iter().next().expect("one member");
                visitor.visit_enum(Variant { key, value })
            }
            Value::Object(m) => Err(de::Error::invalid_length(m.len(), &"an object of one member, its kind")),
            other => Err(de::Error::invalid_type(unexpected(other), &"one of the names listed")),
        }
    }

    /// A plain number, or a text a person wrote it as (`"0,1"`, `"0.1"`:
    /// a decimal comma wherever a number is text; a ratio as a fraction,
    /// `"1/4"`); other texts as serde says.
    fn deserialize_f64<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Error> {
        match self.0 {
            Value::String(s) if let Some(v) = written_number(s) => visitor.visit_f64(v),
            _ => self.deserialize_any(visitor),
        }
    }

    fn deserialize_f32<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, Error> {
        self.deserialize_f64(visitor)
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 char str string
        bytes byte_buf unit unit_struct seq tuple tuple_struct map identifier ignored_any
    }
}

impl<'de> de::SeqAccess<'de> for Seq<'de> {
    type Error = Error;

    fn next_element_seed<T: DeserializeSeed<'de>>(&mut self, seed: T) -> Result<Option<T::Value>, Error> {
        self.0.next().map(|v| seed.deserialize(Strict(v))).transpose()
    }

    fn size_hint(&self) -> Option<usize> {
        Some(self.0.len())
    }
}

impl<'de> de::MapAccess<'de> for Members<'de> {
    type Error = Error;

    fn next_key_seed<K: DeserializeSeed<'de>>(&mut self, seed: K) -> Result<Option<K::Value>, Error> {
        match self.iter.next() {
            Some((k, v)) => {
                self.value = Some(v);
                seed.deserialize(k.as_str().into_deserializer()).map(Some)
            }
            None => Ok(None),
        }
    }

    fn next_value_seed<V: DeserializeSeed<'de>>(&mut self, seed: V) -> Result<V::Value, Error> {
        let value = self.value.take().ok_or_else(|| de::Error::custom("a value without its key"))?;
        seed.deserialize(Strict(value))
    }

    fn size_hint(&self) -> Option<usize> {
        Some(self.iter.len())
    }
}

/// An externally tagged enum's variant with its data, `{"key": value}`.
struct Variant<'de> {
    key: &'de str,
    value: &'de Value,
}

impl<'de> de::EnumAccess<'de> for Variant<'de> {
    type Error = Error;
    type Variant = Self;

    fn variant_seed<V: DeserializeSeed<'de>>(self, seed: V) -> Result<(V::Value, Self), Error> {
        let name = seed.deserialize(StrDeserializer::<Error>::new(self.key))?;
        Ok((name, self))
    }
}

impl<'de> de::VariantAccess<'de> for Variant<'de> {
    type Error = Error;

    fn unit_variant(self) -> Result<(), Error> {
        match self.value {
            Value::Null => Ok(()),
            other => Err(de::Error::invalid_type(unexpected(other), &"null")),
        }
    }
    fn newtype_variant_seed<T: DeserializeSeed<'de>>(self, seed: T) -> Result<T::Value, Error> {
        seed.deserialize(Strict(self.value))
    }
    fn tuple_variant<V: Visitor<'de>>(self, _: usize, visitor: V) -> Result<V::Value, Error> {
        Strict(self.value).deserialize_any(visitor)
    }
    fn struct_variant<V: Visitor<'de>>(self, fields: &'static [&'static str], visitor: V) -> Result<V::Value, Error> {
        Strict(self.value).deserialize_struct("", fields, visitor)
    }
}

/// A finite number written as text (`"0,1"`), or a fraction of two (`"1/4"`, `"2,5 / 3"`).
fn written_number(s: &str) -> Option<f64> {
    let number = |s: &str| crate::units::number(s.trim()).filter(|v| v.is_finite());
    let value = match s.split_once('/') {
        Some((p, q)) => number(p)? / number(q)?,
        None => number(s)?,
    };
    value.is_finite().then_some(value)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    /// Numbers as text a person writes: a decimal comma, a fraction; not a
    /// fraction by zero, nor a word.
    #[test]
    fn numbers_as_written() {
        assert_eq!(written_number("0,25"), Some(0.25));
        assert_eq!(written_number("1/4"), Some(0.25));
        assert_eq!(written_number(" 2,5 / 5 "), Some(0.5));
        for bad in ["1/0", "a/4", "1/4/2", "mucho", ""] {
            assert_eq!(written_number(bad), None, "{bad}");
        }
    }

    #[derive(Debug, Deserialize)]
    #[allow(dead_code)]
    struct Point {
        at: [f64; 3],
    }

    fn read(v: Value) -> Result<Point, Error> {
        Point::deserialize(Strict(&v))
    }

    /// Arrays of the right length only, and a struct only from an object.
    #[test]
    fn lengths_and_objects_are_enforced() {
        assert!(read(serde_json::json!({"at": [1, 2, 3]})).is_ok());
        let long = read(serde_json::json!({"at": [1, 2, 3, 4]})).unwrap_err().to_string();
        assert!(long.contains("invalid length 4"), "{long}");
        assert!(read(serde_json::json!({"at": [1, 2]})).is_err());
        assert!(read(serde_json::json!([[1, 2, 3]])).is_err());
    }
}

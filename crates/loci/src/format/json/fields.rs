//! One object of a problem file read field by field: its raw fields in the order written,
//! each value checked for the kind it must be, with a suggestion for a misspelt name.

use super::error::*;
use serde::de::{Deserialize, Deserializer, MapAccess, Visitor};
use serde_json::value::RawValue;
use std::borrow::Cow;
use std::fmt;

/// A field name, borrowed when it has no escapes.
pub(super) struct Key<'a>(Cow<'a, str>);

impl<'de> Deserialize<'de> for Key<'de> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Key<'de>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a field name")
            }
            fn visit_borrowed_str<E>(self, v: &'de str) -> Result<Key<'de>, E> {
                Ok(Key(Cow::Borrowed(v)))
            }
            fn visit_str<E>(self, v: &str) -> Result<Key<'de>, E> {
                Ok(Key(Cow::Owned(v.to_string())))
            }
        }
        d.deserialize_str(V)
    }
}

/// The fields of one JSON object, in the order written (repeats kept).
pub(super) struct Fields<'a>(Vec<(Cow<'a, str>, &'a RawValue)>);

impl<'de> Deserialize<'de> for Fields<'de> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Fields<'de>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an object")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut m: A) -> Result<Fields<'de>, A::Error> {
                let mut v = Vec::new();
                while let Some((k, raw)) = m.next_entry::<Key<'de>, &'de RawValue>()? {
                    v.push((k.0, raw));
                }
                Ok(Fields(v))
            }
        }
        d.deserialize_map(V)
    }
}

impl<'a> Fields<'a> {
    /// The fields of `raw`, or `None` when it is not an object.
    pub(super) fn of(raw: &'a RawValue) -> Option<Self> {
        if !raw.get().starts_with('{') {
            return None;
        }
        serde_json::from_str(raw.get()).ok()
    }

    pub(super) fn find(&self, key: &str) -> Option<&'a RawValue> {
        self.0.iter().find(|(k, _)| k == key).map(|(_, v)| *v)
    }
}

/// The items of array `raw` (none when it is not an array).
pub(super) fn items(raw: &RawValue) -> Vec<&RawValue> {
    if !raw.get().starts_with('[') {
        return Vec::new();
    }
    serde_json::from_str(raw.get()).unwrap_or_default()
}

/// A value as a message shows it: scalars as written (cut short), containers by kind.
pub(super) fn found(raw: &str) -> String {
    match raw.as_bytes().first() {
        Some(b'{') => "an object".into(),
        Some(b'[') => match serde_json::from_str::<Vec<&RawValue>>(raw) {
            Ok(v) if v.is_empty() => "an empty array".into(),
            Ok(v) if v.len() == 1 => "an array of 1 item".into(),
            Ok(v) => format!("an array of {} items", v.len()),
            Err(_) => "an array".into(),
        },
        _ if raw.chars().count() > 40 => {
            let cut: String = raw.chars().take(37).collect();
            format!("{cut}...")
        }
        _ => raw.to_string(),
    }
}

/// A hint for a number written as a string.
pub(super) fn quoted_number_hint(raw: &str) -> &'static str {
    let inner = raw.strip_prefix('"').and_then(|r| r.strip_suffix('"'));
    match inner {
        Some(s) if s.trim().parse::<f64>().is_ok() => " (numbers are written without quotes)",
        _ => "",
    }
}

/// What a value must be, for messages and checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Expect {
    /// A handle of a param, an entity or a constraint (the word).
    Handle(&'static str),
    Group,
    Number,
    Bool,
    I32,
    Count,
}

impl Expect {
    pub(super) fn describe(self) -> String {
        match self {
            Expect::Handle(what) => format!("{} {what} handle (a positive integer)", article(what)),
            Expect::Group => "a group (an integer from 0 to 4294967295)".into(),
            Expect::Number => "a number".into(),
            Expect::Bool => "true or false".into(),
            Expect::I32 => "an integer".into(),
            Expect::Count => "a whole number (0 or more)".into(),
        }
    }

    pub(super) fn plural(self) -> String {
        match self {
            Expect::Handle(what) => format!("{what} handles"),
            Expect::Number => "numbers".into(),
            other => other.describe(),
        }
    }
}

/// A parsed scalar.
#[derive(Clone, Copy, Debug)]
pub(super) enum Scalar {
    U(u64),
    I(i64),
    F(f64),
    B(bool),
}

/// Reads scalar `raw` as `want`; the error is the message about its value.
pub(super) fn scalar(raw: &str, want: Expect) -> Result<Scalar, String> {
    let wrong = || {
        format!(
            "expected {}, found {}{}",
            want.describe(),
            found(raw),
            quoted_number_hint(raw)
        )
    };
    let is_number = raw
        .as_bytes()
        .first()
        .is_some_and(|b| *b == b'-' || b.is_ascii_digit());
    match want {
        Expect::Bool => match raw {
            "true" => Ok(Scalar::B(true)),
            "false" => Ok(Scalar::B(false)),
            _ => Err(wrong()),
        },
        Expect::Number => {
            if !is_number {
                return Err(wrong());
            }
            match raw.parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(Scalar::F(v)),
                _ => Err(format!(
                    "expected a finite number, found {}, which is too large for a double",
                    found(raw)
                )),
            }
        }
        Expect::Handle(_) | Expect::Group | Expect::Count => {
            if !is_number {
                return Err(wrong());
            }
            match raw.parse::<u64>() {
                Ok(v) => Ok(Scalar::U(v)),
                Err(_) if raw.bytes().all(|b| b == b'-' || b.is_ascii_digit()) => {
                    if raw.starts_with('-') {
                        Err(wrong())
                    } else {
                        Ok(Scalar::U(u64::MAX))
                    }
                }
                Err(_) => Err(wrong()),
            }
        }
        Expect::I32 => {
            if !is_number {
                return Err(wrong());
            }
            match raw.parse::<i64>() {
                Ok(v) => Ok(Scalar::I(v)),
                Err(_) => Err(wrong()),
            }
        }
    }
}

/// An object's own handle: 1 or more.
pub(super) fn handle_value(raw: &str, what: &'static str) -> Result<u32, String> {
    let v = reference_value(raw, what)?;
    if v == 0 {
        return Err(format!(
            "expected {}, found 0: handles start at 1",
            Expect::Handle(what).describe()
        ));
    }
    Ok(v)
}

/// A reference to another object. 0 reads (as it always has), and a solve reports that no
/// object has it when the field is one the type uses.
pub(super) fn reference_value(raw: &str, what: &'static str) -> Result<u32, String> {
    let Scalar::U(v) = scalar(raw, Expect::Handle(what))? else {
        unreachable!("handles are read as unsigned")
    };
    u32::try_from(v).map_err(|_| {
        format!(
            "expected {}, found {}, larger than the largest handle, 4294967295",
            Expect::Handle(what).describe(),
            found(raw)
        )
    })
}

pub(super) fn group_value(raw: &str) -> Result<u32, String> {
    let Scalar::U(v) = scalar(raw, Expect::Group)? else {
        unreachable!("groups are read as unsigned")
    };
    u32::try_from(v).map_err(|_| {
        format!(
            "expected {}, found {}",
            Expect::Group.describe(),
            found(raw)
        )
    })
}

pub(super) fn number_value(raw: &str) -> Result<f64, String> {
    match scalar(raw, Expect::Number)? {
        Scalar::F(v) => Ok(v),
        _ => unreachable!("numbers are read as floats"),
    }
}

pub(super) fn bool_value(raw: &str) -> Result<bool, String> {
    match scalar(raw, Expect::Bool)? {
        Scalar::B(v) => Ok(v),
        _ => unreachable!("flags are read as booleans"),
    }
}

pub(super) fn i32_value(raw: &str) -> Result<i32, String> {
    let Scalar::I(v) = scalar(raw, Expect::I32)? else {
        unreachable!("integers are read as signed")
    };
    i32::try_from(v).map_err(|_| {
        format!(
            "expected an integer from -2147483648 to 2147483647, found {}",
            found(raw)
        )
    })
}

pub(super) fn count_value(raw: &str) -> Result<usize, String> {
    let Scalar::U(v) = scalar(raw, Expect::Count)? else {
        unreachable!("counts are read as unsigned")
    };
    Ok(usize::try_from(v).unwrap_or(usize::MAX))
}

/// The closest of `names` to `word`, when it is close enough to be a slip.
pub(super) fn suggest<'n>(word: &str, names: impl IntoIterator<Item = &'n str>) -> Option<&'n str> {
    let w = word.to_ascii_lowercase().replace(['-', ' '], "_");
    names
        .into_iter()
        .map(|n| (edit_distance(&w, n), n))
        .filter(|(d, n)| *d <= 2.max(n.len() / 4))
        .min_by_key(|(d, _)| *d)
        .map(|(_, n)| n)
}

pub(super) fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for j in 0..b.len() {
            let cur = row[j + 1];
            row[j + 1] = if ca == b[j] {
                prev
            } else {
                1 + prev.min(row[j]).min(row[j + 1])
            };
            prev = cur;
        }
    }
    row[b.len()]
}

/// `"a", "b" and "c"`.
pub(super) fn quoted_list(names: &[&str]) -> String {
    let q: Vec<String> = names.iter().map(|n| format!("\"{n}\"")).collect();
    match q.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        _ => q.join(""),
    }
}

/// `expected one of "a", "b", "c"`.
pub(super) fn one_of(names: &[&str]) -> String {
    let q: Vec<String> = names.iter().map(|n| format!("\"{n}\"")).collect();
    format!("expected one of {}", q.join(", "))
}

/// One JSON object being read: its fields, which have been used, and how to name it.
pub(super) struct Obj<'a> {
    pub(super) text: &'a str,
    pub(super) raw: &'a RawValue,
    pub(super) name: String,
    /// Put before field names in messages: `options.` for the solve options.
    pub(super) prefix: &'static str,
    pub(super) fields: Vec<(Cow<'a, str>, &'a RawValue)>,
    used: Vec<bool>,
}

impl<'a> Obj<'a> {
    /// `raw` as an object named `name`; an error when it is not one or repeats a field.
    pub(super) fn new(text: &'a str, raw: &'a RawValue, name: String) -> Result<Self, JsonError> {
        let Some(Fields(fields)) = Fields::of(raw) else {
            return Err(JsonError::new(
                Some(pos(text, raw)),
                &name,
                "",
                format!("expected an object, found {}", found(raw.get())),
            ));
        };
        for (i, (k, v)) in fields.iter().enumerate() {
            if fields[..i].iter().any(|(k2, _)| k2 == k) {
                // (An object repeating a field: the later value would silently win.)
                return Err(JsonError::new(
                    Some(pos(text, v)),
                    &name,
                    k,
                    format!("field \"{k}\" appears twice"),
                ));
            }
        }
        let used = vec![false; fields.len()];
        Ok(Obj {
            text,
            raw,
            name,
            prefix: "",
            fields,
            used,
        })
    }

    pub(super) fn position(&self) -> Position {
        pos(self.text, self.raw)
    }

    pub(super) fn at(&self, raw: &RawValue) -> Position {
        pos(self.text, raw)
    }

    /// An error about `field` at `raw` (the object when `None`); `message` writes the field
    /// as `{f}`, replaced by its label (`"options.tolerance"`).
    pub(super) fn err(&self, raw: Option<&RawValue>, field: &str, message: String) -> JsonError {
        let position = raw.map_or_else(|| self.position(), |r| self.at(r));
        let label = format!("{}{field}", self.prefix);
        let message = message.replacen("{f}", &label, 1);
        JsonError::new(Some(position), &self.name, &label, message)
    }

    pub(super) fn get(&mut self, key: &str) -> Option<&'a RawValue> {
        let i = self.fields.iter().position(|(k, _)| k == key)?;
        self.used[i] = true;
        Some(self.fields[i].1)
    }

    /// Field `key`, which must be there: `needs` says what it holds.
    pub(super) fn need(
        &mut self,
        key: &str,
        needs: impl FnOnce() -> String,
    ) -> Result<&'a RawValue, JsonError> {
        match self.get(key) {
            Some(raw) => Ok(raw),
            None => Err(self.err(
                None,
                key,
                format!("field \"{{f}}\" is missing; it must be {}", needs()),
            )),
        }
    }

    pub(super) fn value<T>(
        &mut self,
        key: &str,
        read: impl Fn(&str) -> Result<T, String>,
    ) -> Result<Option<T>, JsonError> {
        let Some(raw) = self.get(key) else {
            return Ok(None);
        };
        read(raw.get())
            .map(Some)
            .map_err(|m| self.err(Some(raw), key, format!("field \"{{f}}\": {m}")))
    }

    /// An optional reference to another object.
    pub(super) fn handle(
        &mut self,
        key: &str,
        what: &'static str,
    ) -> Result<Option<u32>, JsonError> {
        self.value(key, |r| reference_value(r, what))
    }

    /// A reference the object needs.
    pub(super) fn need_ref(&mut self, key: &str, what: &'static str) -> Result<u32, JsonError> {
        self.need(key, || Expect::Handle(what).describe())?;
        Ok(self.handle(key, what)?.unwrap_or_default())
    }

    /// The object's own handle, `h`.
    pub(super) fn own_handle(&mut self, what: &'static str) -> Result<u32, JsonError> {
        self.need("h", || Expect::Handle(what).describe())?;
        Ok(self
            .value("h", |r| handle_value(r, what))?
            .unwrap_or_default())
    }

    pub(super) fn need_group(&mut self) -> Result<u32, JsonError> {
        self.need("group", || Expect::Group.describe())?;
        Ok(self.value("group", group_value)?.unwrap_or_default())
    }

    /// An array of `N` values read by `read`, each `want`; `items` names them in order.
    pub(super) fn array<T: Copy + Default, const N: usize>(
        &mut self,
        key: &str,
        want: Expect,
        names: &str,
        read: impl Fn(&str) -> Result<T, String>,
    ) -> Result<[T; N], JsonError> {
        let what = || format!("an array of {N} {} {names}", want.plural());
        let raw = self.need(key, what)?;
        let list = items(raw);
        if !raw.get().starts_with('[') || list.len() != N {
            return Err(self.err(
                Some(raw),
                key,
                format!(
                    "field \"{{f}}\": expected {}, found {}",
                    what(),
                    found(raw.get())
                ),
            ));
        }
        let mut out = [T::default(); N];
        for (i, item) in list.iter().enumerate() {
            out[i] = read(item.get())
                .map_err(|m| self.err(Some(item), key, format!("field \"{{f}}[{i}]\": {m}")))?;
        }
        Ok(out)
    }

    pub(super) fn handles<const N: usize>(
        &mut self,
        key: &str,
        what: &'static str,
        names: &str,
    ) -> Result<[u32; N], JsonError> {
        self.array(key, Expect::Handle(what), names, |r| {
            reference_value(r, what)
        })
    }

    /// Fails on the first field not in `allowed`. For the message, `describe` gives the
    /// object's kind (`a param`, `a point_in_2d entity`) and the fields other kinds of it
    /// have.
    pub(super) fn finish(
        &self,
        allowed: &[&[&str]],
        describe: impl FnOnce() -> (String, Vec<&'static str>),
    ) -> Result<(), JsonError> {
        for (i, (k, v)) in self.fields.iter().enumerate() {
            if self.used[i] || allowed.iter().any(|a| a.contains(&k.as_ref())) {
                continue;
            }
            let (kind, elsewhere) = describe();
            let allowed = allowed.concat();
            let has = format!("{kind} has {}", quoted_list(&allowed));
            let message = if elsewhere.contains(&k.as_ref()) {
                format!("field \"{{f}}\" is not one {kind} has; {has}")
            } else {
                match suggest(k, allowed.iter().copied()) {
                    Some(s) => format!("unknown field \"{{f}}\" (did you mean \"{s}\"?); {has}"),
                    None => format!("unknown field \"{{f}}\"; {has}"),
                }
            };
            return Err(self.err(Some(v), k, message));
        }
        Ok(())
    }
}

//! A Function's table given as CSV text (`{"csv": "angle,torque\n0,10\n..."}`),
//! as a lab pastes it from a spreadsheet: two columns, angle and value, an
//! optional header row; `,` `;` or a tab between the columns, a decimal
//! comma in a `;`- or tab-separated sheet (or a quoted cell of a `,` one).

use super::problem::FieldError;
use super::quantity::{Quantity, TableDto};
use crate::i18n::Msg;

/// The table of `text`, or the error of its first bad row at `at` (the
/// `csv` field's pointer).
pub fn table(text: &str, at: &str, max_rows: usize) -> Result<TableDto, FieldError> {
    let first = text.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
    let delimiter = [b'\t', b';', b','].into_iter().find(|d| first.as_bytes().contains(d)).unwrap_or(b',');
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .delimiter(delimiter)
        .flexible(true)
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let (mut angle, mut value) = (Vec::new(), Vec::new());
    for (i, record) in reader.records().enumerate() {
        let row = i + 1;
        let record =
            record.map_err(|e| FieldError::said(at, Msg::new("function-csv-row").arg("row", row).arg("why", e)))?;
        if record.iter().all(str::is_empty) {
            continue;
        }
        if record.len() != 2 {
            let id = if record.len() > 2 && delimiter == b',' { "csv-columns-comma" } else { "csv-columns" };
            return Err(FieldError::said(at, Msg::new(id).arg("row", row).arg("cells", record.len())));
        }
        let number = |cell: &str| crate::units::number(cell).filter(|v| v.is_finite());
        match (number(&record[0]), number(&record[1])) {
            (Some(a), Some(v)) => {
                angle.push(Quantity::Number(a));
                value.push(v);
            }
            // A header row: the first row, not numbers.
            _ if angle.is_empty() && row == 1 => continue,
            _ => {
                let msg =
                    Msg::new("function-csv-numbers").arg("row", row).arg("angle", &record[0]).arg("value", &record[1]);
                return Err(FieldError::said(at, msg));
            }
        }
        if angle.len() > max_rows {
            return Err(FieldError::said(at, Msg::new("function-csv-rows").arg("max", max_rows)));
        }
    }
    if angle.is_empty() {
        return Err(FieldError::said(at, Msg::new("function-csv-empty")));
    }
    Ok(TableDto { angle, value })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows(text: &str) -> Vec<(f64, f64)> {
        let t = table(text, "/csv", 100).unwrap();
        t.angle
            .iter()
            .zip(&t.value)
            .map(|(a, v)| (if let Quantity::Number(a) = a { *a } else { f64::NAN }, *v))
            .collect()
    }

    #[test]
    fn header_delimiters_and_decimal_commas() {
        assert_eq!(rows("phi_deg,M_Nm\n0,10\n90,-5.5\n"), [(0.0, 10.0), (90.0, -5.5)]);
        assert_eq!(rows("0;1,5\r\n180;-2,25\r\n"), [(0.0, 1.5), (180.0, -2.25)]);
        assert_eq!(rows("0\t1e3\n\n1.5\t2\n"), [(0.0, 1000.0), (1.5, 2.0)]);
    }

    #[test]
    fn bad_rows_are_named() {
        assert!(table("0,1\n2,x\n", "/csv", 100).unwrap_err().message.starts_with("row 2:"));
        assert!(table("0,1,2\n", "/csv", 100).unwrap_err().message.contains("3 columns"));
        // An unquoted decimal comma where commas separate the columns: how to write it.
        assert!(table("0,1,5\n", "/csv", 100).unwrap_err().message.contains("in quotes (\"0,02\")"));
        assert_eq!(rows("0,\"1,5\"\n90,\"-2,25\"\n"), [(0.0, 1.5), (90.0, -2.25)]);
        assert!(table("a,b\n", "/csv", 100).unwrap_err().message.contains("no rows"));
        assert!(table("0,1\n1,2\n2,3\n", "/csv", 2).unwrap_err().message.contains("more than 2"));
    }
}

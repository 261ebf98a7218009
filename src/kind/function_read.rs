//! Functions of the cycle angle read from their wire form (a constant, an
//! expression, segments, a table or a table pasted as CSV) into the engine's
//! [`Function`], every error at its pointer, under the limits in force.

use super::quantity::{
    Errors, FunctionDto, FunctionSpec, InterpolationDto, Quantity, SegmentDto, TableDto, UNIT_MAX_LENGTH, unit_msg,
};
use crate::engine::expr::Expr;
use crate::engine::function::{Function, Interpolation, Segment, Table};
use crate::i18n::Msg;
use crate::units::{self, Dim};

impl Errors {
    /// A function of `phi` with values of dimension `dim`, over [0, period].
    pub fn function(&mut self, f: &FunctionDto, dim: Dim, period: f64, at: &str) -> Option<Function> {
        self.function_of(f, dim, period, at, &["phi"])
    }

    /// A function whose expressions may read `variables` (`phi` first; then
    /// `omega` and `t` where a job integrates in time).
    pub fn function_of(
        &mut self,
        f: &FunctionDto,
        dim: Dim,
        period: f64,
        at: &str,
        variables: &[&str],
    ) -> Option<Function> {
        match f {
            FunctionDto::Constant(Quantity::Text(s)) if self.is_expression(s, variables) => {
                self.refuse(at, Msg::new("field-expression").arg("text", s))
            }
            FunctionDto::Constant(q) => self.quantity(q, dim, at).map(Function::Constant),
            FunctionDto::Spec(spec) => self.function_spec(spec, dim, period, at, variables),
        }
    }

    /// A text that is no quantity but an expression of `variables` (`"20*t"`).
    fn is_expression(&self, text: &str, variables: &[&str]) -> bool {
        let (length, depth) = (self.limits.expression_length, self.limits.expression_depth);
        units::parse_quantity(text).is_err()
            && Expr::compile_with(text, variables, &self.constants, length, depth).is_ok_and(|e| e.constant().is_none())
    }

    fn function_spec(&mut self, s: &FunctionSpec, dim: Dim, period: f64, at: &str, vars: &[&str]) -> Option<Function> {
        let scale = match &s.unit {
            Some(u) if u.chars().count() > UNIT_MAX_LENGTH => {
                let msg = Msg::new("field-at-most-characters").arg("max", UNIT_MAX_LENGTH);
                return self.refuse(&format!("{at}/unit"), msg);
            }
            Some(u) => match units::unit_factor(u, dim) {
                Ok(k) => k,
                Err(e) => return self.refuse(&format!("{at}/unit"), unit_msg(&e)),
            },
            None => 1.0,
        };
        let tabular = s.table.is_some() || s.csv.is_some();
        if s.interpolation.is_some() && !tabular {
            self.say(&format!("{at}/interpolation"), Msg::new("function-table-only"));
        }
        let angle_scale = match &s.angle_unit {
            Some(_) if !tabular => return self.refuse(&format!("{at}/angle_unit"), Msg::new("function-table-only")),
            Some(u) if u.chars().count() > UNIT_MAX_LENGTH => {
                let msg = Msg::new("field-at-most-characters").arg("max", UNIT_MAX_LENGTH);
                return self.refuse(&format!("{at}/angle_unit"), msg);
            }
            Some(u) => match units::unit_factor(u, Dim::ANGLE) {
                Ok(k) => k,
                Err(e) => return self.refuse(&format!("{at}/angle_unit"), unit_msg(&e)),
            },
            None => 1.0,
        };
        let csv = match &s.csv {
            Some(text) => match super::function_csv::table(text, &format!("{at}/csv"), self.limits.table_rows) {
                Ok(t) => Some(t),
                Err(e) => {
                    self.list.push(e);
                    return None;
                }
            },
            None => None,
        };
        let (table, table_at) = match (&s.table, &csv) {
            (Some(t), None) => (Some(t), format!("{at}/table")),
            (None, Some(t)) => (Some(t), format!("{at}/csv")),
            (None, None) => (None, String::new()),
            (Some(_), Some(_)) => return self.refuse(at, Msg::new("function-one-of")),
        };
        match (&s.expr, &s.segments, table) {
            (Some(e), None, None) => {
                self.expr_of(e, &format!("{at}/expr"), vars).map(|e| Function::Expr(e.scaled(scale)))
            }
            (None, Some(segs), None) => self.segments(segs, scale, period, &format!("{at}/segments"), vars),
            (None, None, Some(t)) => {
                let interp = s.interpolation.unwrap_or(InterpolationDto::Linear);
                let t = scaled_angles(t, angle_scale);
                self.table(&t, interp, scale, period, &table_at)
            }
            _ => self.refuse(at, Msg::new("function-one-of")),
        }
    }

    fn expr_of(&mut self, src: &str, at: &str, variables: &[&str]) -> Option<Expr> {
        let (length, depth) = (self.limits.expression_length, self.limits.expression_depth);
        match Expr::compile_with(src, variables, &self.constants, length, depth) {
            Ok(e) => Some(e),
            Err(e) => {
                let why = super::expression::decimal_comma(src, &e.fault).map_or_else(
                    || super::expression::fault_msg(&e.fault),
                    |n| Msg::new("expr-decimal-comma").arg("number", n),
                );
                // The engine's index counts from 0; a person counts the first character as 1.
                let msg = Msg::new("function-parse").with("why", why).arg("position", e.position + 1);
                self.refuse(at, msg)
            }
        }
    }

    fn segments(&mut self, segs: &[SegmentDto], scale: f64, period: f64, at: &str, vars: &[&str]) -> Option<Function> {
        let max = self.limits.segments;
        if segs.is_empty() || segs.len() > max {
            return self.refuse(at, Msg::new("function-segments-count").arg("max", max));
        }
        let slack = 1e-12 * period;
        let mut out = Vec::with_capacity(segs.len());
        for (i, s) in segs.iter().enumerate() {
            let p = format!("{at}/{i}");
            let from = self.angle(&s.from, &format!("{p}/from"));
            let to = self.angle(&s.to, &format!("{p}/to"));
            let expr = self.expr_of(&s.expr, &format!("{p}/expr"), vars);
            let (Some(from), Some(to), Some(expr)) = (from, to, expr) else { continue };
            if from < -slack || to > period + slack {
                let msg = Msg::new("function-segment-inside").num("from", from).num("to", to).num("period", period);
                self.say(&p, msg);
            } else if to <= from {
                self.say(&p, Msg::new("function-to-after-from"));
            } else {
                out.push((i, Segment { from: from.max(0.0), to: to.min(period), expr: expr.scaled(scale) }));
            }
        }
        out.sort_by(|a, b| a.1.from.total_cmp(&b.1.from));
        for w in out.windows(2) {
            if w[1].1.from < w[0].1.to - slack {
                self.say(&format!("{at}/{}", w[1].0), Msg::new("function-overlaps").arg("other", w[0].0));
            }
        }
        (out.len() == segs.len()).then(|| Function::Segments(out.into_iter().map(|s| s.1).collect()))
    }

    fn table(&mut self, t: &TableDto, interp: InterpolationDto, scale: f64, period: f64, at: &str) -> Option<Function> {
        let n = t.angle.len();
        let max = self.limits.table_rows;
        if n == 0 || n > max {
            return self.refuse(&format!("{at}/angle"), Msg::new("function-angles-count").arg("max", max));
        }
        if t.value.len() != n {
            return self.refuse(at, Msg::new("function-rows").count("angles", n).count("values", t.value.len()));
        }
        let angles: Vec<Option<f64>> =
            t.angle.iter().enumerate().map(|(i, a)| self.angle(a, &format!("{at}/angle/{i}"))).collect();
        let mut angle: Vec<f64> = angles.into_iter().collect::<Option<_>>()?;
        let mut value: Vec<f64> = t.value.iter().map(|v| v * scale).collect();
        if let Some(i) = value.iter().position(|v| !v.is_finite()) {
            return self.refuse(&format!("{at}/value/{i}"), Msg::new("field-finite"));
        }
        if n > 1 && (angle[n - 1] - (angle[0] + period)).abs() <= 1e-12 * period {
            if (value[n - 1] - value[0]).abs() > 1e-12 * value[0].abs().max(1e-300) {
                return self.refuse(&format!("{at}/value/{}", n - 1), Msg::new("function-repeat-first"));
            }
            angle.pop();
            value.pop();
        }
        if let Some(i) = (1..angle.len()).find(|&i| angle[i] <= angle[i - 1]) {
            return self.refuse(&format!("{at}/angle/{i}"), Msg::new("function-increasing"));
        }
        if angle[0] < 0.0 || *angle.last().unwrap_or(&0.0) >= period {
            return self.refuse(&format!("{at}/angle"), Msg::new("function-angles-period").num("period", period));
        }
        let interpolation = match interp {
            InterpolationDto::Linear => Interpolation::Linear,
            InterpolationDto::Step => Interpolation::Step,
            InterpolationDto::Spline if angle.len() < 3 => return self.refuse(at, Msg::new("function-spline-rows")),
            InterpolationDto::Spline => Interpolation::Spline,
        };
        Some(Function::Table(Table::new(angle, value, interpolation, period)))
    }
}

/// A table whose angles given as numbers are in a unit of `scale` rad.
fn scaled_angles(t: &TableDto, scale: f64) -> TableDto {
    let angle = t
        .angle
        .iter()
        .map(|a| match a {
            Quantity::Number(x) => Quantity::Number(x * scale),
            text => text.clone(),
        })
        .collect();
    TableDto { angle, value: t.value.clone() }
}

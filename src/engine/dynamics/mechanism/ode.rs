//! The mechanism as the integrator sees it: the ODE y = (q, q̇, W) of its
//! [`Equations`], projected after each step, with the guards of its
//! rolling contacts with friction ([`super::grip`]) and their changes.

use super::equations::Equations;
use super::grip::{Grip, Grips, Mode};
use crate::engine::dynamics::{Crossing, EventKind, Model, Stopped};
use crate::engine::kinetostatics::Frame;

/// The ODE the integrator sees: y = (q, q̇, W).
impl Model for Equations<'_> {
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        if self.stopped_at_fold().is_some() {
            return dy.fill(f64::NAN);
        }
        let n = self.n;
        let (q, qd) = (&y[..n], &y[n..2 * n]);
        if let Some(power) = self.plain(t, q, qd, &mut dy[n..2 * n]) {
            dy[..n].copy_from_slice(qd);
            dy[2 * n] = power;
            return;
        }
        match self.general_motion(t, q, qd, false) {
            Some(m) => {
                dy[..n].copy_from_slice(qd);
                dy[n..2 * n].copy_from_slice(&m.qdd);
                dy[2 * n] = m.forces.iter().zip(qd).map(|(f, v)| f * v).sum();
            }
            // A singular matrix: the stepper rejects the step and retries smaller.
            None => dy.fill(f64::NAN),
        }
    }

    fn angle(&self, y: &[f64]) -> f64 {
        self.input(&y[..self.n], None).0
    }

    fn speed(&self, y: &[f64]) -> f64 {
        self.input(&y[..self.n], Some(&y[self.n..2 * self.n])).1
    }

    fn project(&self, y: &mut [f64]) -> f64 {
        Equations::project(self, y)
    }

    /// The folds held so far: the energy is held until the first (a run made
    /// again from t = 0 holds it as the first run did).
    fn restart(&self) {
        self.held_at.borrow_mut().clear();
        *self.held.borrow_mut() = self.start.clone();
        *self.history.borrow_mut() = vec![(0.0, self.start.clone())];
    }

    /// Each grip's two guards, then each other one-sided contact's normal
    /// force N (≥ 0 while they press).
    fn guards(&self, t: f64, y: &[f64]) -> Vec<f64> {
        let count = 2 * self.grips.len() + self.one_sided.len();
        if count == 0 {
            return Vec::new();
        }
        let (q, qd) = (&y[..self.n], &y[self.n..2 * self.n]);
        let modes = self.held.borrow().modes.clone();
        let Some(motion) = self.motion(t, q, qd, false) else { return vec![f64::NAN; count] };
        let m = &self.p.mechanism;
        let guard = |(g, mode): (&Grip, Mode)| match Frame::of(m, g.joint, q, qd) {
            Some(frame) => g.guards(mode, &frame, &motion.lambda),
            None => [f64::NAN; 2],
        };
        let normal = |&(joint, row): &(usize, usize)| match Frame::of(m, joint, q, qd) {
            Some(frame) => frame.parts([-motion.lambda[row], -motion.lambda[row + 1]])[0],
            None => f64::NAN,
        };
        let mut out: Vec<f64> = self.grips.iter().zip(modes).flat_map(guard).collect();
        out.extend(self.one_sided.iter().map(normal));
        out
    }

    fn stops(&self, k: usize) -> bool {
        k % 2 == 1 || k >= 2 * self.grips.len()
    }

    /// Guard 2i (grip i's mode ends): it slips against the tangential
    /// force rolling needs, or, its slip ended, rolls again from here (its
    /// rolling row's offset the arc slipped) if μN covers that force, else
    /// slips on the other way. Guard 2i + 1, or a one-sided contact's
    /// after the grips': its normal force reached 0.
    fn cross(&self, k: usize, t: f64, y: &[f64]) -> Crossing {
        let opens = |index: usize| {
            let joint = self.p.mechanism.joints[index].name.clone();
            Crossing::Stop(Stopped::ContactOpens { joint, index, t })
        };
        if let Some(&(index, _)) = k.checked_sub(2 * self.grips.len()).and_then(|i| self.one_sided.get(i)) {
            return opens(index);
        }
        let (i, grip) = (k / 2, self.grips[k / 2]);
        if k % 2 == 1 {
            return opens(grip.joint);
        }
        let (q, qd) = (&y[..self.n], &y[self.n..2 * self.n]);
        let rolled = self.held.borrow().modes[i] == Mode::Roll;
        if !rolled {
            let raw = self.system(q, None).phi[grip.roll_row] + self.held.borrow().slipped[i];
            let mut held = self.held.borrow_mut();
            held.slipped[i] = raw;
            held.modes[i] = Mode::Roll;
        }
        let kind = if !rolled && self.guards(t, y)[2 * i] >= 0.0 {
            EventKind::Roll
        } else {
            // F_t as rolling needs it: the slip runs against it.
            let ft = match (self.motion(t, q, qd, false), Frame::of(&self.p.mechanism, grip.joint, q, qd)) {
                (Some(m), Some(frame)) => grip.parts(&frame, &m.lambda)[1],
                _ => 0.0,
            };
            self.held.borrow_mut().modes[i] = Mode::Slip(if ft > 0.0 { -1.0 } else { 1.0 });
            EventKind::Slip
        };
        self.history.borrow_mut().push((t, self.held.borrow().clone()));
        Crossing::Switch(kind, grip.joint)
    }
}

impl Equations<'_> {
    /// The grips' modes at the start: rolling where μN covers the force
    /// rolling needs, else slipping against it (each decided in turn).
    pub fn settle(&mut self, y: &[f64]) {
        for i in 0..self.grips.len() {
            if self.guards(0.0, y)[2 * i] < 0.0 {
                self.cross(2 * i, 0.0, y);
            }
        }
        self.start = self.held.borrow().clone();
    }

    /// The grips as they were at time t (for a sample after the run).
    pub fn grips_at(&self, t: f64) -> Grips {
        let history = self.history.borrow();
        let last = history.iter().rev().find(|(at, _)| *at <= t).or(history.first());
        last.map_or_else(|| self.start.clone(), |(_, g)| g.clone())
    }
}

//! The order in which the bodies' equations are solved, as the notes solve
//! a mechanism by hand: its structural groups (Assur groups, with the
//! inputs' bodies as groups of their own), found from the ground outwards
//! and solved from the last. A group is a smallest set S of bodies not yet
//! placed whose joints to what is placed and among themselves, with the
//! driving efforts that act on them, have as many unknowns as S has
//! equations, 3·|S|: a crank with its pin and its motor torque (2 + 1), a
//! dyad of two bodies and three pairs (3·2). Each joint's unknowns are its
//! rows of the constraints (a pin's two, a slider's normal force and
//! couple, a sliding contact's normal force).

use crate::engine::model::{BodyId, Coordinate, Mechanism};

/// One group: its bodies, the joints whose reactions its equations give,
/// and the inputs whose efforts they give.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Group {
    pub bodies: Vec<BodyId>,
    pub joints: Vec<usize>,
    pub inputs: Vec<usize>,
}

/// Groups searched among subsets of up to this many bodies; a mechanism
/// with more bodies than [`SEARCHED`] is one group.
const LARGEST: usize = 3;
const SEARCHED: usize = 40;

/// The groups in the order their equations are solved (the last placed
/// first); the bodies no group takes make one group at the end.
pub fn solving_order(m: &Mechanism) -> Vec<Group> {
    let bodies = m.bodies.len();
    let mut placed = vec![false; bodies];
    placed[0] = true;
    let (mut joints_used, mut inputs_used) = (vec![false; m.joints.len()], vec![false; m.drivers.len()]);
    let mut groups = Vec::new();
    while let Some(group) = (bodies <= SEARCHED).then(|| next(m, &placed, &joints_used, &inputs_used)).flatten() {
        for &b in &group.bodies {
            placed[b] = true;
        }
        group.joints.iter().for_each(|&k| joints_used[k] = true);
        group.inputs.iter().for_each(|&i| inputs_used[i] = true);
        groups.push(group);
    }
    let rest: Vec<BodyId> = (1..bodies).filter(|&b| !placed[b]).collect();
    if !rest.is_empty() {
        let joints = (0..m.joints.len()).filter(|&k| !joints_used[k]).collect();
        let inputs = (0..m.drivers.len()).filter(|&i| !inputs_used[i]).collect();
        groups.push(Group { bodies: rest, joints, inputs });
    }
    groups.reverse();
    groups
}

/// The smallest group among the bodies not placed, if any.
fn next(m: &Mechanism, placed: &[bool], joints_used: &[bool], inputs_used: &[bool]) -> Option<Group> {
    let free: Vec<BodyId> = (1..m.bodies.len()).filter(|&b| !placed[b]).collect();
    for size in 1..=LARGEST.min(free.len()) {
        let mut pick = (0..size).collect::<Vec<_>>();
        loop {
            let set: Vec<BodyId> = pick.iter().map(|&i| free[i]).collect();
            if let Some(group) = group_of(m, &set, placed, (joints_used, inputs_used)) {
                return Some(group);
            }
            if !advance(&mut pick, free.len()) {
                break;
            }
        }
    }
    None
}

/// The next combination of `pick.len()` indices below `n`, in order; false after the last.
fn advance(pick: &mut [usize], n: usize) -> bool {
    let k = pick.len();
    let Some(i) = (0..k).rev().find(|&i| pick[i] < n - k + i) else { return false };
    pick[i] += 1;
    for j in i + 1..k {
        pick[j] = pick[j - 1] + 1;
    }
    true
}

/// `set` as a group, if its unknowns are as many as its equations.
fn group_of(
    m: &Mechanism,
    set: &[BodyId],
    placed: &[bool],
    (joints_used, inputs_used): (&[bool], &[bool]),
) -> Option<Group> {
    let known = |b: BodyId| placed[b] || set.contains(&b);
    let touches = |bs: &[BodyId]| bs.iter().any(|b| set.contains(b)) && bs.iter().all(|&b| known(b));
    let joints: Vec<usize> = (0..m.joints.len()).filter(|&k| !joints_used[k] && touches(&m.joints[k].bodies)).collect();
    let inputs: Vec<usize> =
        (0..m.drivers.len()).filter(|&i| !inputs_used[i] && touches(&driven_bodies(m, i))).collect();
    let unknowns: usize =
        joints.iter().map(|&k| Mechanism::joint_rows(&m.joints[k].kind)).sum::<usize>() + inputs.len();
    // Every body of the set tied to the rest of it or to what is placed (no two groups in one).
    let tied =
        set.len() == 1 || set.iter().all(|&b| joints.iter().filter(|&&k| m.joints[k].bodies.contains(&b)).count() >= 2);
    (unknowns == 3 * set.len() && tied).then(|| Group { bodies: set.to_vec(), joints, inputs })
}

/// The bodies input i's effort acts between.
fn driven_bodies(m: &Mechanism, i: usize) -> Vec<BodyId> {
    let d = &m.drivers[i];
    match d.actuator.map_or(d.coordinate, Coordinate::Joint) {
        Coordinate::Joint(k) => m.joints[k].bodies.to_vec(),
        Coordinate::Point { body, .. } | Coordinate::Body(body) => vec![0, body],
    }
}

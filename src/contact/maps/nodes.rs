//! The node solves of a covered surface ([`super::surface`]): every distinct (ln s, ln η) point is
//! solved once, whichever panels and refinement rounds want it, and each solve starts from a nearby
//! answer.
//!
//! Input: the points a refinement round wants, each with an optional guess of λ (the panel's
//! previous interpolant there); output: the solved [`CoveredNode`]s, kept by point.
//!
//! Reuse: the Lobatto grids are built so that a point shared by two grids has the same bits in both
//! (exact panel ends and midpoints, and the points of degree n are those of 2n with even index,
//! computed from the same quotient), so neighbouring panels share their edge nodes and a doubled
//! or halved panel keeps the nodes it had, through one table keyed by the point.
//!
//! Warm starts: the layer solver's load loop starts from a guess of λ (`CoveredProblem::node_from`;
//! it changes the answer only within the loop's stopping tolerance). A point with a guess from the
//! previous interpolant starts from it; the others are solved in chains of equal ln s, in order of
//! ln η, each from the previous answer of its chain (λ changes by a few per cent between
//! neighbouring nodes). Chains are solved in parallel (rayon).

use super::covered_problem::{CoveredNode, CoveredProblem};
use super::FrictionMapError;
use rayon::prelude::*;
use std::collections::HashMap;

/// Distinct node warnings kept (a bound on the report's length).
const MAX_WARNINGS: usize = 8;
/// How the layer solvers' warnings of a solve short of its tolerance begin
/// (crate::contact::body::layer).
const SHORT_OF_TOL: &str = "tolerance not reached";

/// The solved nodes of one surface, by point.
#[derive(Debug, Default)]
pub(super) struct NodeTable {
    nodes: HashMap<(u64, u64), CoveredNode>,
    /// Node solves made.
    pub solves: usize,
    /// Largest error estimate of the layer solver at the nodes.
    pub largest_estimate: f64,
    /// Distinct warnings of the node solves (at most [`MAX_WARNINGS`]).
    pub warnings: Vec<String>,
}

fn key(x: f64, y: f64) -> (u64, u64) {
    (x.to_bits(), y.to_bits())
}

impl NodeTable {
    /// The node at (x, y), if solved.
    pub fn get(&self, x: f64, y: f64) -> Option<&CoveredNode> {
        self.nodes.get(&key(x, y))
    }

    /// Solve the points of `wanted` = (x, y, guess of λ) not solved yet (module doc), at `tol`.
    pub fn solve(
        &mut self,
        problem: &CoveredProblem,
        wanted: &[(f64, f64, Option<f64>)],
        tol: f64,
    ) -> Result<(), FrictionMapError> {
        // chains: one per distinct x, the points in order of y, each point once
        let mut chains: Vec<Vec<(f64, f64, Option<f64>)>> = Vec::new();
        let mut chain_of: HashMap<u64, usize> = HashMap::new();
        let mut seen: HashMap<(u64, u64), ()> = HashMap::new();
        for &(x, y, guess) in wanted {
            if self.get(x, y).is_some() || seen.insert(key(x, y), ()).is_some() {
                continue;
            }
            let c = *chain_of.entry(x.to_bits()).or_insert_with(|| {
                chains.push(Vec::new());
                chains.len() - 1
            });
            chains[c].push((x, y, guess));
        }
        for c in &mut chains {
            c.sort_by(|p, q| p.1.total_cmp(&q.1));
        }
        let solved: Vec<Vec<(f64, f64, CoveredNode)>> = chains
            .par_iter()
            .map(|chain| {
                let mut out = Vec::with_capacity(chain.len());
                let mut previous: Option<f64> = None;
                for &(x, y, guess) in chain {
                    // d ln N′/d ln λ is left to the solver's closed form (NaN)
                    let start = guess.or(previous).map(|l| (l, f64::NAN));
                    let node = problem.node_from(x, y, tol, start)?;
                    previous = Some(node.ln_lambda.exp());
                    out.push((x, y, node));
                }
                Ok(out)
            })
            .collect::<Result<_, FrictionMapError>>()?;
        for (x, y, node) in solved.into_iter().flatten() {
            self.solves += 1;
            self.largest_estimate = self.largest_estimate.max(node.error_estimate);
            // a node short of its tolerance is not reported as such: its estimate enters the
            // surface's (Λ_x·Λ_y times the largest node estimate, super::surface), which warns
            // when the total exceeds the map's tolerance
            for w in node
                .warnings
                .iter()
                .filter(|w| !w.starts_with(SHORT_OF_TOL))
            {
                if self.warnings.len() < MAX_WARNINGS && !self.warnings.contains(w) {
                    self.warnings.push(w.clone());
                }
            }
            self.nodes.insert(key(x, y), node);
        }
        Ok(())
    }
}

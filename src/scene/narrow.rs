//! The narrow phase: each pair the broad phase kept, by the stepper of its
//! shapes ([`AnyPair`]), on this thread or on every core.

use super::params::{SceneParams, SceneQueryError};
use super::query::Scene;
use super::report::{PairReport, SceneReport, SceneWorkspace};
use crate::ca::{time_of_impact, AnyPair, MeshWorkspace};
use crate::Float;

impl<T: Float> Scene<'_, T> {
    /// The narrow phase over the pairs of the last
    /// [`broad_phase`](Self::broad_phase), in order, on this thread.
    ///
    /// # Errors
    /// As [`query`](Self::query).
    pub fn narrow_phase<'w>(
        &self,
        ws: &'w mut SceneWorkspace<T>,
        params: &SceneParams<T>,
    ) -> Result<&'w SceneReport<T>, SceneQueryError> {
        ws.report.pairs.clear();
        let mut work = PairWork::default();
        for &(a, b) in &ws.candidates {
            let (ia, ib) = (a as usize, b as usize);
            let (report, w) = self.run_pair(ia, ib, params, &mut ws.mesh)?;
            work.add(w);
            ws.report.pairs.push(report);
        }
        Ok(finish(ws, self.bodies.len(), work))
    }

    /// One pair's query, with the stepper of its shapes.
    fn run_pair(
        &self,
        a: usize,
        b: usize,
        params: &SceneParams<T>,
        mesh_ws: &mut MeshWorkspace<T>,
    ) -> Result<(PairReport<T>, PairWork), SceneQueryError> {
        let (ba, bb) = (&self.bodies[a], &self.bodies[b]);
        let (ma, mb) = (&ba.motion, &bb.motion);
        // Every pair of kinds through the one dispatch.
        let mut pair = AnyPair::try_new(ba.shape, bb.shape)?
            .try_with_mesh_params(params.mesh)?
            .with_workspace(core::mem::take(mesh_ws));
        let r = time_of_impact(&mut pair, ma, mb, &params.ca);
        let (evq_skipped, evq_evaluated) = pair.bound_counts();
        *mesh_ws = pair.into_workspace();
        let report = r?;
        let node_pairs = report.work.node_pairs;
        let mut work = PairWork {
            evq_skipped,
            evq_evaluated,
            ..PairWork::default()
        };
        work.iterations = u64::from(report.iterations);
        Ok((
            PairReport {
                a,
                b,
                report,
                node_pairs,
            },
            work,
        ))
    }
}

/// The counters one pair's query adds.
#[derive(Clone, Copy, Debug, Default)]
struct PairWork {
    iterations: u64,
    evq_skipped: u64,
    evq_evaluated: u64,
}

impl PairWork {
    fn add(&mut self, o: Self) {
        self.iterations += o.iterations;
        self.evq_skipped += o.evq_skipped;
        self.evq_evaluated += o.evq_evaluated;
    }
}

/// The per-body earliest contacts and the counters, from the pairs' reports.
fn finish<T: Float>(ws: &mut SceneWorkspace<T>, bodies: usize, work: PairWork) -> &SceneReport<T> {
    let report = &mut ws.report;
    report.earliest.clear();
    report.earliest.resize(bodies, None);
    for p in &report.pairs {
        if let Some(t) = p.report.outcome.earliest_possible_contact() {
            for (me, other) in [(p.a, p.b), (p.b, p.a)] {
                let slot = &mut report.earliest[me];
                if slot.is_none_or(|(best, _)| t < best) {
                    *slot = Some((t, other));
                }
            }
        }
    }
    report.stats.iterations = work.iterations;
    report.stats.evq_skipped = work.evq_skipped;
    report.stats.evq_evaluated = work.evq_evaluated;
    &ws.report
}

#[cfg(feature = "parallel")]
impl<T: Float + Send + Sync> Scene<'_, T> {
    /// As [`query`](Self::query), with the narrow phase spread over rayon's
    /// threads: the same report, pair for pair, whatever the thread count.
    ///
    /// # Errors
    /// As [`query`](Self::query).
    #[cfg_attr(docsrs, doc(cfg(feature = "parallel")))]
    pub fn par_query<'w>(
        &self,
        ws: &'w mut SceneWorkspace<T>,
        params: &SceneParams<T>,
    ) -> Result<&'w SceneReport<T>, SceneQueryError> {
        self.broad_phase(ws, params, |_, _| true)?;
        self.par_narrow_phase(ws, params)
    }

    /// As [`narrow_phase`](Self::narrow_phase), across rayon's threads (one
    /// mesh workspace per thread's run of pairs); the reports come back in
    /// pair order.
    ///
    /// # Errors
    /// As [`query`](Self::query).
    #[cfg_attr(docsrs, doc(cfg(feature = "parallel")))]
    pub fn par_narrow_phase<'w>(
        &self,
        ws: &'w mut SceneWorkspace<T>,
        params: &SceneParams<T>,
    ) -> Result<&'w SceneReport<T>, SceneQueryError> {
        use rayon::prelude::*;
        let results: alloc::vec::Vec<Result<(PairReport<T>, PairWork), SceneQueryError>> = ws
            .candidates
            .par_iter()
            .map_init(MeshWorkspace::new, |mesh, &(a, b)| {
                self.run_pair(a as usize, b as usize, params, mesh)
            })
            .collect();
        ws.report.pairs.clear();
        let mut work = PairWork::default();
        for r in results {
            let (report, w) = r?;
            work.add(w);
            ws.report.pairs.push(report);
        }
        Ok(finish(ws, self.bodies.len(), work))
    }
}

//! The leaf pairs one step hands to the next (`proofs/09-ca-toi.md`,
//! Lemma 9.4).

/// How many leaf pairs a step hands to the next one.
pub(super) const SEEDS: usize = 4;

/// The leaf pairs (indices into the trees' leaves) with the least steps
/// measured in one step, least first.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Seeds {
    pub(super) pairs: [(u32, u32); SEEDS],
    steps: [f64; SEEDS],
    pub(super) len: usize,
}

impl Seeds {
    pub(super) fn insert(&mut self, step: f64, pair: (u32, u32)) {
        let mut k = self.len.min(SEEDS - 1);
        if self.len == SEEDS && step.total_cmp(&self.steps[k]).is_ge() {
            return;
        }
        while k > 0 && step < self.steps[k - 1] {
            self.steps[k] = self.steps[k - 1];
            self.pairs[k] = self.pairs[k - 1];
            k -= 1;
        }
        self.steps[k] = step;
        self.pairs[k] = pair;
        self.len = (self.len + 1).min(SEEDS);
    }

    /// Where `pair` is among the seeds.
    pub(super) fn position(&self, pair: (u32, u32)) -> Option<usize> {
        let mut k = 0;
        while k < self.len {
            if self.pairs[k] == pair {
                return Some(k);
            }
            k += 1;
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::{Seeds, SEEDS};

    #[test]
    fn seeds_keep_the_least_steps_in_order() {
        let mut s = Seeds::default();
        let steps = [0.5, 0.1, 0.9, 0.3, 0.05, 0.7, 0.2];
        for (k, &x) in steps.iter().enumerate() {
            s.insert(x, (k as u32, 0));
        }
        // An independent answer: sort a copy.
        let mut sorted: alloc::vec::Vec<(f64, u32)> = steps
            .iter()
            .enumerate()
            .map(|(k, &x)| (x, k as u32))
            .collect();
        sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
        assert_eq!(s.len, SEEDS);
        for (k, want) in sorted.iter().take(SEEDS).enumerate() {
            assert_eq!((s.steps[k], s.pairs[k].0), *want);
        }
        assert_eq!((s.position((4, 0)), s.position((2, 0))), (Some(0), None));
        let mut one = Seeds::default();
        one.insert(1.0, (7, 8));
        assert_eq!((one.len, one.pairs[0]), (1, (7, 8)));
    }
}

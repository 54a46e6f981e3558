//! `bake --shard K/N`: the K-th of N disjoint, stable slices of a preset list, so that a job
//! scheduler (Slurm array jobs, Kubernetes indexed Jobs, GNU parallel, a render-farm queue)
//! can split one preset file over N independent `bake` processes.
//!
//! - **K counts from 0**: `0/N` to `(N-1)/N`, like Slurm's `SLURM_ARRAY_TASK_ID` with
//!   `--array=0-(N-1)` and Kubernetes' `JOB_COMPLETION_INDEX`.
//! - Preset `i` of the list (0-based, in file order) belongs to shard `i mod N`. The slice
//!   depends only on the list, so re-running shard K bakes the same presets; the N slices are
//!   disjoint and together hold every preset once. Appending presets to the end of the file
//!   moves none of the existing ones to another shard.
//! - A shard can be empty (N larger than the number of presets): that is not an error.
//!
//! ```
//! use bake::shard::Shard;
//! let s: Shard = "1/3".parse().unwrap();
//! assert_eq!(s.select(&["a", "b", "c", "d", "e"]), vec!["b", "e"]);
//! assert!("3/3".parse::<Shard>().is_err()); // K counts from 0
//! ```

use std::fmt;
use std::str::FromStr;

/// Shard `index` of `count` (`index < count`, `count ≥ 1`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    index: u32,
    count: u32,
}

impl Shard {
    /// Shard `index` of `count`; `None` unless `count ≥ 1` and `index < count`.
    pub fn new(index: u32, count: u32) -> Option<Shard> {
        (index < count).then_some(Shard { index, count })
    }

    /// K, counting from 0.
    pub fn index(self) -> u32 {
        self.index
    }

    /// N, the number of shards.
    pub fn count(self) -> u32 {
        self.count
    }

    /// Whether item `i` of a list (0-based) is in this shard: `i mod N == K`.
    pub fn contains(self, i: usize) -> bool {
        i % self.count as usize == self.index as usize
    }

    /// The items of `list` in this shard, in list order.
    pub fn select<T: Clone>(self, list: &[T]) -> Vec<T> {
        list.iter()
            .enumerate()
            .filter(|&(i, _)| self.contains(i))
            .map(|(_, t)| t.clone())
            .collect()
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

/// Why a `K/N` text is not a shard; [`Display`](fmt::Display) gives one line that quotes the
/// text and names the problem.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ShardError {
    /// The text as given.
    pub text: String,
    /// What is wrong with it.
    pub message: String,
}

impl fmt::Display for ShardError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "--shard '{}': {}", self.text, self.message)
    }
}

impl std::error::Error for ShardError {}

impl FromStr for Shard {
    type Err = ShardError;

    /// Parses `K/N`: two whole numbers (ASCII digits only), `N ≥ 1`, `0 ≤ K < N`.
    fn from_str(text: &str) -> Result<Shard, ShardError> {
        let err = |message: String| ShardError {
            text: text.to_string(),
            message,
        };
        let Some((k, n)) = text.split_once('/') else {
            return Err(err(
                "expected K/N, shard K of N with K counting from 0 (e.g. 0/4 to 3/4)".to_string(),
            ));
        };
        let number = |s: &str, what: &str| -> Result<u32, ShardError> {
            if s.is_empty() || !s.bytes().all(|b| b.is_ascii_digit()) {
                return Err(err(format!(
                    "{what} '{s}' is not a whole number (expected K/N, e.g. 0/4)"
                )));
            }
            s.parse()
                .map_err(|_| err(format!("{what} '{s}' is too large")))
        };
        let k = number(k, "K")?;
        let n = number(n, "N")?;
        if n == 0 {
            return Err(err("N must be at least 1".to_string()));
        }
        Shard::new(k, n).ok_or_else(|| {
            err(format!(
                "K must be 0 to {} for N = {n} (K counts from 0)",
                n - 1
            ))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_selects() {
        let s: Shard = "0/1".parse().unwrap();
        assert_eq!(s.select(&[1, 2, 3]), vec![1, 2, 3]);
        let s: Shard = "2/3".parse().unwrap();
        assert_eq!((s.index(), s.count(), s.to_string()), (2, 3, "2/3".into()));
        assert_eq!(s.select(&[0, 1, 2, 3, 4, 5, 6]), vec![2, 5]);
        assert!(s.select(&[0, 1]).is_empty());
    }

    #[test]
    fn slices_are_disjoint_and_cover_the_list() {
        let list: Vec<usize> = (0..23).collect();
        for n in 1..30u32 {
            let mut seen = vec![0; list.len()];
            for k in 0..n {
                for i in Shard::new(k, n).unwrap().select(&list) {
                    seen[i] += 1;
                }
            }
            assert!(seen.iter().all(|&c| c == 1), "N = {n}: {seen:?}");
        }
    }

    #[test]
    fn rejects_malformed_text() {
        for (text, needle) in [
            ("3", "expected K/N"),
            ("", "expected K/N"),
            ("a/b", "K 'a' is not a whole number"),
            ("1/b", "N 'b' is not a whole number"),
            ("/4", "K '' is not a whole number"),
            ("-1/4", "K '-1' is not a whole number"),
            ("+1/4", "K '+1' is not a whole number"),
            (" 1/4", "is not a whole number"),
            ("1/2/3", "N '2/3' is not a whole number"),
            ("0/0", "N must be at least 1"),
            ("5/4", "K must be 0 to 3 for N = 4"),
            ("4/4", "K counts from 0"),
            ("0/99999999999", "N '99999999999' is too large"),
        ] {
            let e = text.parse::<Shard>().unwrap_err();
            let line = e.to_string();
            assert!(line.contains(needle), "{text:?}: {line}");
            assert!(line.starts_with(&format!("--shard '{text}': ")), "{line}");
            assert!(!line.contains('\n'), "{line}");
        }
    }
}

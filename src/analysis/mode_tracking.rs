//! Mode tracking across speeds by the modal assurance criterion (MAC).
//!
//! `MAC(a, b) = |aᴴ b|² / ((aᴴ a)(bᴴ b))` of two complex shapes on the
//! translational DOFs (x, y of every node): 1 for the same shape up to a
//! complex factor, 0 for orthogonal ones (Allemang and Brown, Proc. 1st IMAC,
//! 1982). Between neighbouring speeds the modes of one speed are linked to
//! those of the next by the assignment of largest total MAC (the Hungarian
//! method, O(n³)); a link below [`MIN_LINK_MAC`] is no link (a mode that
//! leaves the listed range, or a new one entering it).

use nalgebra::Complex;

use crate::fe::{DOF_PER_NODE, DOF_X, DOF_Y};

type C64 = Complex<f64>;

/// The smallest MAC that links two modes of neighbouring speeds. A degenerate
/// planar pair at standstill has MAC 1/2 with each circular mode it splits
/// into, so the bar sits below that.
pub const MIN_LINK_MAC: f64 = 0.3;

/// The translational part (x, y of every node) of a shape on all DOFs.
pub fn translations(shape: &[C64]) -> Vec<C64> {
    shape
        .chunks(DOF_PER_NODE)
        .flat_map(|node| [node[DOF_X], node[DOF_Y]])
        .collect()
}

/// `MAC(a, b)` of two complex shapes of equal length (0 when either is zero).
pub fn mac(a: &[C64], b: &[C64]) -> f64 {
    assert_eq!(a.len(), b.len(), "MAC of shapes of different lengths");
    let (mut ab, mut aa, mut bb) = (C64::new(0.0, 0.0), 0.0, 0.0);
    for (x, y) in a.iter().zip(b) {
        ab += x.conj() * y;
        aa += x.norm_sqr();
        bb += y.norm_sqr();
    }
    if aa > 0.0 && bb > 0.0 {
        ab.norm_sqr() / (aa * bb)
    } else {
        0.0
    }
}

/// For every shape of `next`, the index of the shape of `previous` it
/// continues, from the assignment of largest total MAC; `None` when its MAC
/// with the assigned one is below [`MIN_LINK_MAC`] or no shape is left.
pub fn link(previous: &[Vec<C64>], next: &[Vec<C64>]) -> Vec<Option<usize>> {
    let cost: Vec<Vec<f64>> = next
        .iter()
        .map(|b| previous.iter().map(|a| 1.0 - mac(a, b)).collect())
        .collect();
    assignment(&cost)
        .into_iter()
        .enumerate()
        .map(|(i, j)| j.filter(|&j| cost[i][j] <= 1.0 - MIN_LINK_MAC))
        .collect()
}

/// Minimum-cost assignment of the rows of a rectangular cost matrix to
/// distinct columns (Hungarian method with potentials, after Kuhn and
/// Munkres); a row gets `None` when there are fewer columns than rows.
pub fn assignment(cost: &[Vec<f64>]) -> Vec<Option<usize>> {
    let rows = cost.len();
    let cols = cost.first().map_or(0, Vec::len);
    if rows == 0 || cols == 0 {
        return vec![None; rows];
    }
    // Square the problem with zero-cost dummies (1-based indices inside).
    let n = rows.max(cols);
    let c = |i: usize, j: usize| -> f64 {
        if i <= rows && j <= cols {
            cost[i - 1][j - 1]
        } else {
            0.0
        }
    };
    let (mut u, mut v) = (vec![0.0; n + 1], vec![0.0; n + 1]);
    let mut owner = vec![0usize; n + 1]; // owner[j]: row assigned to column j
    let mut way = vec![0usize; n + 1];
    for i in 1..=n {
        owner[0] = i;
        let mut j0 = 0;
        let mut minv = vec![f64::INFINITY; n + 1];
        let mut used = vec![false; n + 1];
        loop {
            used[j0] = true;
            let i0 = owner[j0];
            let mut delta = f64::INFINITY;
            let mut j1 = 0;
            for j in 1..=n {
                if used[j] {
                    continue;
                }
                let reduced = c(i0, j) - u[i0] - v[j];
                if reduced < minv[j] {
                    minv[j] = reduced;
                    way[j] = j0;
                }
                if minv[j] < delta {
                    delta = minv[j];
                    j1 = j;
                }
            }
            for j in 0..=n {
                if used[j] {
                    u[owner[j]] += delta;
                    v[j] -= delta;
                } else {
                    minv[j] -= delta;
                }
            }
            j0 = j1;
            if owner[j0] == 0 {
                break;
            }
        }
        loop {
            let j1 = way[j0];
            owner[j0] = owner[j1];
            j0 = j1;
            if j0 == 0 {
                break;
            }
        }
    }
    let mut out = vec![None; rows];
    for j in 1..=cols {
        if (1..=rows).contains(&owner[j]) {
            out[owner[j] - 1] = Some(j - 1);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(re: f64, im: f64) -> C64 {
        C64::new(re, im)
    }

    #[test]
    fn mac_is_one_for_a_scaled_shape_and_zero_for_an_orthogonal_one() {
        let a = [c(1.0, 0.0), c(0.5, -0.2), c(0.0, 1.0)];
        let scaled: Vec<C64> = a.iter().map(|x| x * c(-2.0, 3.0)).collect();
        assert!((mac(&a, &scaled) - 1.0).abs() < 1e-15);
        let b = [c(0.0, 0.0), c(0.0, 0.0), c(1.0, 0.0)];
        let d = [c(1.0, 0.0), c(0.0, 0.0), c(0.0, 0.0)];
        assert_eq!(mac(&b, &d), 0.0);
        // A planar mode against the circular one it splits into: 1/2.
        let planar = [c(1.0, 0.0), c(0.0, 0.0)];
        let circular = [c(1.0, 0.0), c(0.0, 1.0)];
        assert!((mac(&planar, &circular) - 0.5).abs() < 1e-15);
    }

    /// The Hungarian method against every permutation of a 5×5 problem and
    /// on rectangular ones.
    #[test]
    fn assignment_is_the_cheapest_permutation() {
        let cost: Vec<Vec<f64>> = (0..5)
            .map(|i| {
                (0..5)
                    .map(|j| ((i * 7 + j * 13) % 11) as f64 + 0.1 * (i * j) as f64)
                    .collect()
            })
            .collect();
        let total = |p: &[usize]| (0..5).map(|i| cost[i][p[i]]).sum::<f64>();
        let mut best = f64::INFINITY;
        let mut perm = [0, 1, 2, 3, 4];
        // Heap's algorithm over all 120 permutations.
        fn heap(k: usize, p: &mut [usize; 5], f: &mut impl FnMut(&[usize; 5])) {
            if k == 1 {
                f(p);
                return;
            }
            for i in 0..k {
                heap(k - 1, p, f);
                let j = if k % 2 == 0 { i } else { 0 };
                p.swap(j, k - 1);
            }
        }
        heap(5, &mut perm, &mut |p| best = best.min(total(p)));
        let found: Vec<usize> = assignment(&cost).into_iter().map(Option::unwrap).collect();
        assert!((total(&found) - best).abs() < 1e-12, "{found:?}");
        // More rows than columns: one row is left without.
        let tall = vec![vec![1.0, 0.0], vec![0.0, 1.0], vec![0.5, 0.5]];
        let a = assignment(&tall);
        assert_eq!(a[0], Some(1));
        assert_eq!(a[1], Some(0));
        assert_eq!(a[2], None);
        // More columns than rows.
        assert_eq!(assignment(&[vec![3.0, 1.0, 2.0]]), vec![Some(1)]);
    }

    #[test]
    fn link_follows_the_shapes_not_the_order() {
        let a = vec![c(1.0, 0.0), c(0.0, 0.0), c(0.0, 0.0)];
        let b = vec![c(0.0, 0.0), c(1.0, 0.0), c(0.0, 0.0)];
        let z = vec![c(0.0, 0.0), c(0.0, 0.0), c(1.0, 0.0)];
        // Next speed lists b first, then a slightly rotated a, then a new z.
        let a2 = vec![c(1.0, 0.1), c(0.05, 0.0), c(0.0, 0.0)];
        let links = link(&[a.clone(), b.clone()], &[b, a2, z]);
        assert_eq!(links, vec![Some(1), Some(0), None]);
    }
}

//! Sorting by a float key through one instantiation of the sort: each closure given to
//! `sort_by` compiles to its own copy of the sorting code (several KB of wasm each).

/// The indices of `keys` in ascending key order (`total_cmp`); ties keep index order,
/// so sorting by one key and then by another is lexicographic in (second, first).
pub fn by_key(keys: &[f64]) -> Vec<usize> {
    let mut keyed: Vec<(f64, u32)> = keys.iter().copied().zip(0..).collect();
    keyed.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    keyed.into_iter().map(|(_, i)| i as usize).collect()
}

/// Sorts floats ascending (`total_cmp`).
pub fn floats(v: &mut [f64]) {
    let sorted: Vec<f64> = by_key(v).into_iter().map(|i| v[i]).collect();
    v.copy_from_slice(&sorted);
}

/// `items` reordered by `key`, ascending.
pub fn sorted<T: Copy>(items: &[T], key: impl Fn(&T) -> f64) -> Vec<T> {
    let keys: Vec<f64> = items.iter().map(key).collect();
    by_key(&keys).into_iter().map(|i| items[i]).collect()
}

#[cfg(test)]
mod tests {
    #[test]
    fn ties_keep_order() {
        assert_eq!(super::by_key(&[2.0, 1.0, 2.0, -0.5]), vec![3, 1, 0, 2]);
        assert_eq!(super::sorted(&[(1, 5.0), (2, 3.0)], |p| p.1), vec![(2, 3.0), (1, 5.0)]);
    }
}

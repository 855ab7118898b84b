//! A dense row-major grid of samples (rows index s, columns index t).

/// A `rows × cols` table of values stored row by row.
///
/// Row `i` corresponds to the `i`-th s (or u) sample and column `j` to the `j`-th t (or v)
/// sample. MATLAB's `meshgrid(u, v)` puts `u` along columns, which is why Codice 14 compares
/// against `X'`; this type stores that transposed layout directly.
#[derive(Debug, Clone, PartialEq)]
pub struct Grid<T> {
    rows: usize,
    cols: usize,
    data: Vec<T>,
}

impl<T> Grid<T> {
    /// Builds the grid from `f(i, j)`.
    ///
    /// # Panics
    /// If `rows · cols` exceeds [`crate::error::MAX_ELEMENTS`]; see [`Grid::try_from_fn`].
    pub fn from_fn(rows: usize, cols: usize, f: impl FnMut(usize, usize) -> T) -> Self {
        Self::try_from_fn(rows, cols, f).expect("grid too large")
    }

    /// Builds the grid from `f(i, j)`.
    ///
    /// # Errors
    /// [`crate::error::Error::TooLarge`] if `rows · cols` overflows or exceeds
    /// [`crate::error::MAX_ELEMENTS`] (nothing is allocated).
    pub fn try_from_fn(
        rows: usize,
        cols: usize,
        mut f: impl FnMut(usize, usize) -> T,
    ) -> crate::error::Result<Self> {
        let len = crate::error::size_product("grid cells (rows × cols)", rows, cols)?;
        if len == 0 {
            // no cells: nothing to call f for, however many rows or columns
            return Ok(Self {
                rows,
                cols,
                data: Vec::new(),
            });
        }
        let mut data = Vec::with_capacity(len);
        for i in 0..rows {
            for j in 0..cols {
                data.push(f(i, j));
            }
        }
        Ok(Self { rows, cols, data })
    }

    /// Wraps row-major `data` of length `rows * cols`; `None` if the length differs (or the
    /// product overflows).
    pub fn from_vec(rows: usize, cols: usize, data: Vec<T>) -> Option<Self> {
        (rows.checked_mul(cols) == Some(data.len())).then_some(Self { rows, cols, data })
    }

    /// Number of rows (s samples).
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns (t samples).
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// The value at row `i`, column `j`.
    ///
    /// # Panics
    /// If the index is out of range.
    pub fn get(&self, i: usize, j: usize) -> &T {
        assert!(i < self.rows && j < self.cols, "grid index out of range");
        &self.data[i * self.cols + j]
    }

    /// Row `i` as a slice.
    ///
    /// # Panics
    /// If `i` is out of range.
    pub fn row(&self, i: usize) -> &[T] {
        &self.data[i * self.cols..(i + 1) * self.cols]
    }

    /// All values, row-major.
    pub fn as_slice(&self) -> &[T] {
        &self.data
    }

    /// All values, row-major, mutable (the shape stays fixed).
    pub fn as_mut_slice(&mut self) -> &mut [T] {
        &mut self.data
    }

    /// Applies `f` to every value.
    pub fn map<U>(&self, f: impl FnMut(&T) -> U) -> Grid<U> {
        Grid {
            rows: self.rows,
            cols: self.cols,
            data: self.data.iter().map(f).collect(),
        }
    }
}

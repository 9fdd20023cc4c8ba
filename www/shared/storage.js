// localStorage with JSON, never throwing: a full or disabled storage only means the
// work is kept in memory, never an error in the page.
export function load(key, fallback) {
  try {
    const v = localStorage.getItem(key);
    return v ? JSON.parse(v) : fallback;
  } catch {
    return fallback;
  }
}

/** Stores `value`; false when storage is full or disabled (the work stays in memory). */
export function store(key, value) {
  try {
    localStorage.setItem(key, JSON.stringify(value));
    return true;
  } catch {
    return false;
  }
}

export function forget(key) {
  try {
    localStorage.removeItem(key);
  } catch {
    // Disabled storage holds nothing to forget.
  }
}

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

export function store(key, value) {
  try {
    localStorage.setItem(key, JSON.stringify(value));
  } catch {
    // Storage full or disabled: keep working in memory.
  }
}

// A tab's message line: each message replaces the one before, styled by its kind.

/** A `say(text, kind)` writing into `element` ('' for news, 'warn' or 'error'). */
export function sayInto(element) {
  return (text, kind = '') => {
    const p = document.createElement('p');
    p.className = kind;
    p.textContent = text;
    element.replaceChildren(p);
  };
}

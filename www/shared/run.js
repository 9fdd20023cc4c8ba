// One long worker call at a time behind a Run button, a Cancel button and a progress
// bar: a new run aborts the one before, Cancel aborts, and a failure or a cancellation
// is said; the buttons and the bar follow.

/** `els`: { run, cancel, progress, say }. */
export function runControls({ run, cancel, progress, say }) {
  let abort = null;
  cancel.addEventListener('click', () => abort?.abort());
  return {
    /** Whether a run is under way. */
    get busy() {
      return abort !== null;
    },
    /** Says `message`, then awaits `work({ signal, onProgress })`; never throws. */
    async start(message, work) {
      abort?.abort();
      abort = new AbortController();
      // A keyboard user who started the run keeps a focused control: Cancel while it
      // runs, the run button again after (a disabled button drops focus to the page).
      const keyboard = document.activeElement === run;
      run.disabled = true;
      cancel.disabled = false;
      if (keyboard) cancel.focus();
      progress.value = 0;
      say(message);
      try {
        await work({ signal: abort.signal, onProgress: (f) => { progress.value = f; } });
        progress.value = 1;
      } catch (e) {
        const cancelled = e.name === 'AbortError';
        say(cancelled ? 'Cancelled.' : e.message, cancelled ? 'warn' : 'error');
        progress.value = 0;
      } finally {
        abort = null;
        const refocus = document.activeElement === cancel || (keyboard && document.activeElement === document.body);
        run.disabled = false;
        cancel.disabled = true;
        if (refocus) run.focus();
      }
    },
  };
}

/** Points a disabled-looking download link at `url` and enables it. */
export function offerDownload(link, url) {
  link.href = url;
  link.classList.remove('disabled');
  link.removeAttribute('aria-disabled');
}

/** Takes a download link back (its result is gone or out of date). */
export function withdrawDownload(link) {
  link.removeAttribute('href');
  link.classList.add('disabled');
  link.setAttribute('aria-disabled', 'true');
}

// The worker module has no exports: start it with `new Worker(url, { type: 'module' })`
// and talk to it through PatternSynthClient (patternsynth/client).
export {};

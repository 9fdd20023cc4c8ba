'use client';
// A client component: init() of patternsynth/vector and the worker client, in an effect
// (the README: on the client only, never during render on the server).
import { useEffect } from 'react';
import { report } from './browser-checks.js';

export default function Checks() {
  useEffect(() => { report(); }, []);
  return <p id="checks">Browser checks run in an effect.</p>;
}

// playback.js — the playback clock of the current clip: time, play/pause, loop, speed (0.25×–2×),
// scrubbing, and which clip segment (sign, letter, pause) is under the play head. It never poses the
// avatar itself: the app hands `time_s` to the core each frame.

export const MIN_SPEED = 0.25;
export const MAX_SPEED = 2;

export class Playback {
  constructor() {
    this.duration_s = 0;
    this.time_s = 0;
    this.playing = false;
    this.loop = true;
    this.speed = 1;
    this.segments = [];
    this.listeners = new Set();
  }

  onChange(fn) { this.listeners.add(fn); }
  emit() { for (const fn of this.listeners) fn(this); }

  setClip(duration_s, segments = []) {
    this.duration_s = Math.max(0, duration_s || 0);
    this.segments = segments;
    this.time_s = 0;
    this.emit();
  }

  play() {
    if (this.duration_s <= 0) return;
    if (this.time_s >= this.duration_s) this.time_s = 0;
    this.playing = true;
    this.emit();
  }

  pause() { this.playing = false; this.emit(); }
  toggle() { this.playing ? this.pause() : this.play(); }

  seek(time_s) {
    this.time_s = Math.min(Math.max(0, time_s), this.duration_s);
    this.emit();
  }

  setSpeed(speed) {
    this.speed = Math.min(MAX_SPEED, Math.max(MIN_SPEED, Number(speed) || 1));
    this.emit();
  }

  // Advance by a wall-clock step; returns true when the time changed.
  tick(dt_s) {
    if (!this.playing || this.duration_s <= 0) return false;
    // A frame longer than 0.25 s (tab in background, debugger) would skip whole signs: clamp it.
    let t = this.time_s + Math.min(dt_s, 0.25) * this.speed;
    if (t >= this.duration_s) {
      if (this.loop) t %= this.duration_s;
      else { t = this.duration_s; this.playing = false; }
    }
    this.time_s = t;
    return true;
  }

  currentSegment() {
    const t = this.time_s;
    for (const s of this.segments) if (t >= s.start_s && t < s.end_s) return s;
    return null;
  }

  // The word of the typed phrase being signed: the segment under the play head, or, during a
  // transition, the word being approached (so the caption never flickers off between signs).
  currentWordIndex() {
    const s = this.currentSegment();
    if (s && s.word_index >= 0) return s.word_index;
    const next = this.segments.find((seg) => seg.start_s >= this.time_s && seg.word_index >= 0);
    return next ? next.word_index : -1;
  }
}

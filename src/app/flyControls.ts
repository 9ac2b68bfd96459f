/**
 * Fly camera of the course report §2.6: W, A, S, D move along the view direction v and the left
 * vector l = u × v, and the mouse turns the view through yaw φ and pitch θ with
 *
 *   v = (cos φ cos θ, sin θ, sin φ cos θ),   l = u × v,   u = (0, 1, 0).
 *
 * Yaw is measured from +x towards +z (so φ = −90° looks along three.js's default −z), pitch up
 * from the horizon. Moving the mouse right increases φ (turns right), moving it up increases θ.
 *
 * Input:
 *   W / S (or ↑ / ↓)    forward / back along v
 *   A / D (or ← / →)    left / right along l (horizontal)
 *   Space / E           up          Shift / Q   down
 *   hold F              fast (FAST_FACTOR × speed)
 *   mouse wheel         speed (clamped to [MIN_SPEED, MAX_SPEED])
 *   drag                turns the view (a button held)
 *   L                   pointer lock (Esc releases, the browser's default); while locked the
 *                       mouse turns the view
 *   click, tap          onClick(x, y) (the app drops a stone there), without moving
 *   touch               one-finger drag turns, two-finger drag moves (up = forward, sideways =
 *                       strafe).
 *
 * Movement is velocity × dt, so it does not depend on the frame rate. The camera may dive under the
 * sea down to MIN_HEIGHT (200 m below the mean sea level y = 0), and pitch stays within ±MAX_PITCH.
 *
 * The math (direction, left vector, one movement step, turning) is in pure functions below,
 * unit-tested in Node; FlyControls wires them to DOM events and a three.js camera.
 */
import type { PerspectiveCamera } from 'three';

export type Vec3 = [number, number, number];

export const MAX_PITCH = 89;
export const MIN_HEIGHT = -200;
export const MIN_SPEED = 0.5;
export const MAX_SPEED = 500;
export const DEFAULT_SPEED = 20;
export const FAST_FACTOR = 5;
/** Degrees of turn per pixel of mouse movement. */
export const MOUSE_DEGREES_PER_PIXEL = 0.15;
/** Degrees of turn per pixel of one-finger touch drag. */
export const TOUCH_DEGREES_PER_PIXEL = 0.25;
/** Longest frame a movement step integrates over, so a stalled frame does not teleport the camera. */
export const MAX_STEP_SECONDS = 0.5;

const DEG = Math.PI / 180;

/** The view direction v for yaw φ and pitch θ in degrees (the report's equation; unit length). */
export function viewDirection(yawDeg: number, pitchDeg: number): Vec3 {
  const phi = yawDeg * DEG;
  const theta = pitchDeg * DEG;
  return [Math.cos(phi) * Math.cos(theta), Math.sin(theta), Math.sin(phi) * Math.cos(theta)];
}

/**
 * The left vector l = u × v with u = (0, 1, 0), normalised: (v_z, 0, −v_x)/|…|. It is horizontal
 * and points to the left of the view in three.js's right-handed frame. For a view straight up or
 * down (never reached: pitch is clamped) it falls back to the yaw's left.
 */
export function leftVector(yawDeg: number, pitchDeg: number): Vec3 {
  const [vx, , vz] = viewDirection(yawDeg, pitchDeg);
  const length = Math.hypot(vx, vz);
  if (length < 1e-9) return leftVector(yawDeg, 0);
  return [vz / length, 0, -vx / length];
}

/** Yaw and pitch (degrees) that look along the direction d (need not be unit length). */
export function anglesFromDirection(d: Vec3): { yaw: number; pitch: number } {
  const horizontal = Math.hypot(d[0], d[2]);
  return { yaw: Math.atan2(d[2], d[0]) / DEG, pitch: clampPitch(Math.atan2(d[1], horizontal) / DEG) };
}

export function clampPitch(pitchDeg: number): number {
  return Math.min(MAX_PITCH, Math.max(-MAX_PITCH, pitchDeg));
}

/** Yaw wrapped into (−180, 180]. */
export function wrapYaw(yawDeg: number): number {
  if (yawDeg > -180 && yawDeg <= 180) return yawDeg; // exact: no rounding of values already in range
  const wrapped = ((((yawDeg + 180) % 360) + 360) % 360) - 180;
  return wrapped === -180 ? 180 : wrapped;
}

export function clampSpeed(speed: number): number {
  return Math.min(MAX_SPEED, Math.max(MIN_SPEED, speed));
}

/** Speed after a wheel event of `deltaY` pixels: ×1.2 per 100 px scrolled up, clamped. */
export function speedAfterWheel(speed: number, deltaY: number): number {
  return clampSpeed(speed * Math.pow(1.2, -deltaY / 100));
}

/** New yaw and pitch after turning by a pointer movement of (dx, dy) pixels (dy > 0 is down). */
export function turn(
  yawDeg: number,
  pitchDeg: number,
  dx: number,
  dy: number,
  degreesPerPixel = MOUSE_DEGREES_PER_PIXEL,
): { yaw: number; pitch: number } {
  return { yaw: wrapYaw(yawDeg + dx * degreesPerPixel), pitch: clampPitch(pitchDeg - dy * degreesPerPixel) };
}

/** Which movement keys are held. */
export interface MoveInput {
  forward: boolean;
  back: boolean;
  left: boolean;
  right: boolean;
  up: boolean;
  down: boolean;
  fast: boolean;
}

export const NO_INPUT: Readonly<MoveInput> = Object.freeze({
  forward: false,
  back: false,
  left: false,
  right: false,
  up: false,
  down: false,
  fast: false,
});

/**
 * The camera position after `dt` seconds of holding `input`: the sum of the held directions (v,
 * −v, l, −l, u, −u), normalised so diagonals are not faster, times speed (× FAST_FACTOR when
 * fast) times dt; then y is kept ≥ MIN_HEIGHT.
 */
export function step(position: Vec3, yawDeg: number, pitchDeg: number, input: MoveInput, speed: number, dt: number): Vec3 {
  const v = viewDirection(yawDeg, pitchDeg);
  const l = leftVector(yawDeg, pitchDeg);
  const d: Vec3 = [0, 0, 0];
  const add = (w: Vec3, sign: number) => {
    d[0] += sign * w[0];
    d[1] += sign * w[1];
    d[2] += sign * w[2];
  };
  if (input.forward) add(v, 1);
  if (input.back) add(v, -1);
  if (input.left) add(l, 1);
  if (input.right) add(l, -1);
  if (input.up) add([0, 1, 0], 1);
  if (input.down) add([0, 1, 0], -1);
  const length = Math.hypot(d[0], d[1], d[2]);
  const distance = length > 1e-9 ? ((input.fast ? FAST_FACTOR : 1) * speed * Math.max(0, dt)) / length : 0;
  return [position[0] + d[0] * distance, Math.max(MIN_HEIGHT, position[1] + d[1] * distance), position[2] + d[2] * distance];
}

/**
 * The camera position after a two-finger drag of (dx, dy) pixels: dy < 0 (drag up) moves forward
 * along v, dx > 0 moves right; metresPerPixel scales it.
 */
export function touchMove(position: Vec3, yawDeg: number, pitchDeg: number, dx: number, dy: number, metresPerPixel: number): Vec3 {
  const v = viewDirection(yawDeg, pitchDeg);
  const l = leftVector(yawDeg, pitchDeg);
  const forward = -dy * metresPerPixel;
  const left = -dx * metresPerPixel;
  return [
    position[0] + v[0] * forward + l[0] * left,
    Math.max(MIN_HEIGHT, position[1] + v[1] * forward),
    position[2] + v[2] * forward + l[2] * left,
  ];
}

/** KeyboardEvent.code → which input it drives (physical keys, so WASD works on any layout). */
const KEY_BINDINGS: Record<string, keyof MoveInput> = {
  KeyW: 'forward',
  ArrowUp: 'forward',
  KeyS: 'back',
  ArrowDown: 'back',
  KeyA: 'left',
  ArrowLeft: 'left',
  KeyD: 'right',
  ArrowRight: 'right',
  Space: 'up',
  KeyE: 'up',
  ShiftLeft: 'down',
  ShiftRight: 'down',
  KeyQ: 'down',
  KeyF: 'fast',
};

export function bindingFor(code: string): keyof MoveInput | undefined {
  return Object.hasOwn(KEY_BINDINGS, code) ? KEY_BINDINGS[code] : undefined;
}

/** The on-screen help for these controls. */
export const CONTROLS_HELP =
  'Look: drag, or L to lock the mouse (Esc frees it) · Move: W A S D · up: Space/E · down: Shift/Q · hold F: fast · wheel: speed · Click the sea: drop a stone';

const TEXT_INPUT_TYPES = new Set(['text', 'number', 'search', 'email', 'url', 'password', 'tel']);

/** Whether keys typed now go into a text field (then they do not move the camera). */
function isTextInput(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return false;
  if (target instanceof HTMLInputElement) return TEXT_INPUT_TYPES.has(target.type);
  return target.isContentEditable || target.tagName === 'TEXTAREA' || target.tagName === 'SELECT';
}

function capturePointer(element: HTMLElement, pointerId: number): void {
  try {
    element.setPointerCapture(pointerId);
  } catch {
    // Not an active pointer (e.g. a synthetic event): moves outside the canvas are simply missed.
  }
}

export interface CameraPose {
  position: Vec3;
  yaw: number;
  pitch: number;
}

/** Fly controls for a camera on a canvas; call update(dt) once per frame. dispose() removes the listeners. */
export class FlyControls {
  yaw: number;
  pitch: number;
  /** Metres per second (before the fast modifier). */
  speed = DEFAULT_SPEED;
  readonly input: MoveInput = { ...NO_INPUT };
  /** Called whenever the pose changes (position, yaw or pitch). */
  onChange: (() => void) | null = null;
  /** Called for a click or a tap that did not turn or move the view, at its client coordinates. */
  onClick: ((clientX: number, clientY: number) => void) | null = null;

  private dragging: { pointerId: number; x: number; y: number; moved: number } | null = null;
  private readonly touches = new Map<number, { x: number; y: number; moved: number }>();
  private readonly cleanup: (() => void)[] = [];

  constructor(
    readonly camera: PerspectiveCamera,
    readonly element: HTMLElement,
    pose: CameraPose = { position: [0, 12, 0], yaw: -53.13, pitch: -6.84 },
  ) {
    this.yaw = wrapYaw(pose.yaw);
    this.pitch = clampPitch(pose.pitch);
    camera.position.fromArray(pose.position);
    camera.position.y = Math.max(MIN_HEIGHT, camera.position.y);
    this.applyToCamera();
    this.listen();
  }

  get pose(): CameraPose {
    return { position: this.camera.position.toArray() as Vec3, yaw: this.yaw, pitch: this.pitch };
  }

  set pose(pose: CameraPose) {
    this.camera.position.fromArray(pose.position);
    this.camera.position.y = Math.max(MIN_HEIGHT, this.camera.position.y);
    this.yaw = wrapYaw(pose.yaw);
    this.pitch = clampPitch(pose.pitch);
    this.applyToCamera();
    this.onChange?.();
  }

  /** Whether the pointer is locked to the canvas (then the mouse turns the view). */
  get locked(): boolean {
    return document.pointerLockElement === this.element;
  }

  /** Moves the camera for the held keys over dt seconds (clamped to MAX_STEP_SECONDS). */
  update(dt: number): void {
    const { input } = this;
    if (!(input.forward || input.back || input.left || input.right || input.up || input.down)) return;
    const next = step(this.camera.position.toArray() as Vec3, this.yaw, this.pitch, input, this.speed, Math.min(dt, MAX_STEP_SECONDS));
    this.camera.position.fromArray(next);
    this.applyToCamera();
    this.onChange?.();
  }

  /** Turns by a pointer movement of (dx, dy) pixels. */
  turnBy(dx: number, dy: number, degreesPerPixel = MOUSE_DEGREES_PER_PIXEL): void {
    if (dx === 0 && dy === 0) return;
    const { yaw, pitch } = turn(this.yaw, this.pitch, dx, dy, degreesPerPixel);
    this.yaw = yaw;
    this.pitch = pitch;
    this.applyToCamera();
    this.onChange?.();
  }

  /** Points the camera along v from its position (call after changing yaw, pitch or position). */
  applyToCamera(): void {
    const v = viewDirection(this.yaw, this.pitch);
    const p = this.camera.position;
    this.camera.up.set(0, 1, 0);
    this.camera.lookAt(p.x + v[0], p.y + v[1], p.z + v[2]);
    this.camera.updateMatrixWorld();
  }

  /** Releases every held key (focus lost, tab hidden). */
  releaseKeys(): void {
    Object.assign(this.input, NO_INPUT);
  }

  dispose(): void {
    for (const remove of this.cleanup.splice(0)) remove();
    this.releaseKeys();
  }

  private on<K extends keyof DocumentEventMap>(
    target: HTMLElement | Window | Document,
    type: K,
    handler: (event: DocumentEventMap[K]) => void,
    options?: AddEventListenerOptions,
  ): void {
    target.addEventListener(type, handler as EventListener, options);
    this.cleanup.push(() => target.removeEventListener(type, handler as EventListener, options));
  }

  private listen(): void {
    const element = this.element;
    element.style.touchAction = 'none'; // touch drags turn and move instead of scrolling or zooming

    this.on(window, 'keydown', (event) => {
      if (event.code === 'KeyL' && !isTextInput(event.target) && !this.locked) this.requestLock();
      const binding = bindingFor(event.code);
      if (!binding || isTextInput(event.target) || event.ctrlKey || event.metaKey || event.altKey) return;
      this.input[binding] = true;
      event.preventDefault(); // Space would press a focused button or scroll
    });
    this.on(window, 'keyup', (event) => {
      const binding = bindingFor(event.code);
      if (binding) this.input[binding] = false;
    });
    this.on(window, 'blur', () => this.releaseKeys());
    this.on(document, 'visibilitychange', () => this.releaseKeys());

    this.on(element, 'pointerdown', (event) => {
      if (event.pointerType === 'touch') {
        this.touches.set(event.pointerId, { x: event.clientX, y: event.clientY, moved: 0 });
        capturePointer(element, event.pointerId);
        return;
      }
      if (this.locked) return;
      this.dragging = { pointerId: event.pointerId, x: event.clientX, y: event.clientY, moved: 0 };
      capturePointer(element, event.pointerId);
    });
    this.on(element, 'pointermove', (event) => {
      if (event.pointerType === 'touch') {
        this.touchMoved(event);
        return;
      }
      if (this.locked) {
        this.turnBy(event.movementX, event.movementY);
      } else if (this.dragging && this.dragging.pointerId === event.pointerId) {
        const dx = event.clientX - this.dragging.x;
        const dy = event.clientY - this.dragging.y;
        this.dragging.x = event.clientX;
        this.dragging.y = event.clientY;
        this.dragging.moved += Math.abs(dx) + Math.abs(dy);
        this.turnBy(dx, dy);
      }
    });
    const endPointer = (event: PointerEvent) => {
      if (event.pointerType === 'touch') {
        const touch = this.touches.get(event.pointerId);
        const tap = touch !== undefined && touch.moved < 8 && this.touches.size === 1;
        this.touches.delete(event.pointerId);
        if (tap && event.type === 'pointerup') this.onClick?.(event.clientX, event.clientY);
        return;
      }
      const drag = this.dragging;
      if (!drag || drag.pointerId !== event.pointerId) return;
      this.dragging = null;
      // A click is a press and release that did not turn the view (a drag).
      if (event.type === 'pointerup' && drag.moved < 4) this.onClick?.(event.clientX, event.clientY);
    };
    this.on(element, 'pointerup', endPointer);
    this.on(element, 'pointercancel', endPointer);
    this.on(
      element,
      'wheel',
      (event) => {
        event.preventDefault();
        this.speed = speedAfterWheel(this.speed, event.deltaMode === 1 ? event.deltaY * 33 : event.deltaY);
      },
      { passive: false },
    );
    this.on(element, 'contextmenu', (event) => event.preventDefault());
  }

  private requestLock(): void {
    const element = this.element;
    if (typeof element.requestPointerLock !== 'function') return;
    try {
      // A promise in current browsers; it rejects where pointer lock is unavailable (headless).
      const result = element.requestPointerLock() as unknown;
      if (result instanceof Promise) result.catch(() => undefined);
    } catch {
      // Pointer lock unavailable: dragging still turns.
    }
  }

  private touchMoved(event: PointerEvent): void {
    const previous = this.touches.get(event.pointerId);
    if (!previous) return;
    const dx = event.clientX - previous.x;
    const dy = event.clientY - previous.y;
    this.touches.set(event.pointerId, { x: event.clientX, y: event.clientY, moved: previous.moved + Math.abs(dx) + Math.abs(dy) });
    if (this.touches.size === 1) {
      this.turnBy(dx, dy, TOUCH_DEGREES_PER_PIXEL);
    } else if (this.touches.size === 2) {
      // Each finger's move shifts the midpoint by half of it.
      const next = touchMove(this.camera.position.toArray() as Vec3, this.yaw, this.pitch, dx / 2, dy / 2, this.speed / 100);
      this.camera.position.fromArray(next);
      this.applyToCamera();
      this.onChange?.();
    }
  }
}

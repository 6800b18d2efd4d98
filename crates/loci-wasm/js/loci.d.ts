// Types of the loci package: typed handles (numbers branded by what they name), string-literal
// unions for every kind, typed reports, and the Error subclasses thrown.

declare const brand: unique symbol;
/** A handle: a number at run time, typed by what it names so that one cannot stand for another. */
export type Handle<B extends string> = number & { readonly [brand]: B };

// ---------------------------------------------------------------------------------------------
// Errors

/** Every error loci throws; `object` names the object at fault (`point 104`, `entity 12`,
 * `mate REVO1`, `component door`, `line 7`) when there is one. */
export class LociError extends Error {
  readonly object: string | null;
}
/** The SolveSpace model is invalid: a dangling or wrong reference, a bad handle or number. */
export class ModelError extends LociError {}
/** A solve cannot start: an unknown group or dragged parameter, a bad option. */
export class SolveError extends LociError {}
/** The sketcher refused a call: an unknown shape, a shape of the wrong kind, a bad value. */
export class SketchError extends LociError {}
/** An assembly refused a call: an unknown component, reference or mate. */
export class AssemblyError extends LociError {}
/** A file cannot be read: JSON, a sketch, an assembly or `.slvs`. */
export class FormatError extends LociError {}
/** An argument of the wrong shape: a handle that is not one, a missing drag. */
export class InputError extends LociError {}

/** The version of loci the package was built from. */
export function version(): string;

/** How a solve ended. */
export type Outcome = "okay" | "redundant_okay" | "inconsistent" | "did_not_converge";

// ---------------------------------------------------------------------------------------------
// The SolveSpace model

export type ParamId = Handle<"ParamId">;
export type EntityId = Handle<"EntityId">;
export type CoreConstraintId = Handle<"ConstraintId">;
/** Groups are plain integers: solving a group makes its parameters the unknowns. */
export type GroupId = number;

export type EntityType =
  | "point_in_3d" | "point_in_2d" | "point_n_trans" | "point_n_rot_trans" | "normal_n_rot"
  | "normal_in_3d" | "normal_in_2d" | "distance" | "workplane" | "line_segment" | "cubic"
  | "circle" | "arc_of_circle";

interface EntityBase {
  h: number;
  group: GroupId;
  workplane?: number;
}
/** An entity as in loci's JSON format (docs/format.md). */
export type EntityJson =
  | (EntityBase & { type: "point_in_3d"; params: [number, number, number] })
  | (EntityBase & { type: "point_in_2d"; workplane: number; params: [number, number] })
  | (EntityBase & { type: "point_n_trans"; params: [number, number, number]; base: number; translation: [number, number, number]; times: number })
  | (EntityBase & { type: "point_n_rot_trans"; params: [number, number, number]; base: [number, number, number]; translation: [number, number, number]; rotation: number })
  | (EntityBase & { type: "normal_in_3d"; params: [number, number, number, number] })
  | (EntityBase & { type: "normal_n_rot"; params: [number, number, number, number]; base: [number, number, number, number]; rotation: number })
  | (EntityBase & { type: "normal_in_2d"; workplane: number })
  | (EntityBase & { type: "distance"; param: number })
  | (EntityBase & { type: "workplane"; origin: number; normal: number })
  | (EntityBase & { type: "line_segment"; points: [number, number] })
  | (EntityBase & { type: "cubic"; points: [number, number, number, number] })
  | (EntityBase & { type: "circle"; center: number; normal: number; radius: number })
  | (EntityBase & { type: "arc_of_circle"; workplane: number; normal: number; center: number; start: number; end: number });

/** The 38 constraint types of SolveSpace's library. */
export type ConstraintKind =
  | "points_coincident" | "pt_pt_distance" | "pt_plane_distance" | "pt_line_distance"
  | "pt_face_distance" | "pt_in_plane" | "pt_on_line" | "pt_on_face" | "equal_length_lines"
  | "length_ratio" | "eq_len_pt_line_d" | "eq_pt_ln_distances" | "equal_angle"
  | "equal_line_arc_len" | "symmetric" | "symmetric_horiz" | "symmetric_vert" | "symmetric_line"
  | "at_midpoint" | "horizontal" | "vertical" | "diameter" | "pt_on_circle" | "same_orientation"
  | "angle" | "parallel" | "perpendicular" | "arc_line_tangent" | "cubic_line_tangent"
  | "equal_radius" | "proj_pt_distance" | "where_dragged" | "curve_curve_tangent"
  | "length_difference" | "arc_arc_len_ratio" | "arc_line_len_ratio" | "arc_arc_difference"
  | "arc_line_difference";

/** A constraint as in loci's JSON format (docs/format.md). */
export interface ConstraintJson {
  h: number;
  group: GroupId;
  type: ConstraintKind;
  workplane?: number;
  val?: number;
  pt_a?: number;
  pt_b?: number;
  entity_a?: number;
  entity_b?: number;
  entity_c?: number;
  entity_d?: number;
  other?: boolean;
  other2?: boolean;
  reference?: boolean;
  /** An angle in a workplane whose `val` is signed, counter-clockwise from `entity_a` to `entity_b`. */
  signed?: boolean;
}

/** Solver options of a solve. */
export interface SolveOptions {
  /** Parameters that should move as little as possible. */
  dragged?: ParamId[];
  tolerance?: number;
  max_iterations?: number;
  dragged_scale?: number;
  rank_tolerance?: number;
  verify_conflicts_up_to?: number;
  /** `false`: end where Newton's steps end, as SolveSpace does (default `true`: the solution
   * nearest the drawing). */
  nearest?: boolean;
  /** Write 2D angles as SolveSpace does, so that with `nearest: false` an under-constrained
   * sketch ends where SolveSpace's would (default `false`). */
  solvespace_angles?: boolean;
}

/** The report of a solve of one group. */
export interface SolveReport {
  outcome: Outcome;
  dof: number;
  /** The constraints named redundant, conflicting or unsatisfied. */
  failed: CoreConstraintId[];
  failed_entities?: EntityId[];
  iterations: number;
  residual: number;
  unknowns: number;
  equations: number;
  components: number;
}

export type DiagnosisMember = { constraint: CoreConstraintId } | { entity: EntityId };

/** The diagnosis of a group (see `loci check`). */
export interface Diagnosis {
  group: GroupId;
  outcome: Outcome;
  dof: number;
  unknowns: number;
  equations: number;
  rank: number;
  iterations: number;
  residual: number;
  /**
   * Sets of constraints that cannot hold together. `verified`: the set was shown minimal (it
   * fails alone, and without any one member the rest solves); false where that was not shown.
   */
  conflicting: { members: DiagnosisMember[]; verified: boolean }[];
  redundant: { members: DiagnosisMember[]; excess: number; involved?: DiagnosisMember[] }[];
  freedoms: { entity: EntityId; kind: EntityType; dof: number; [more: string]: unknown }[];
  [more: string]: unknown;
}

/** One group of a `.slvs` file solved in order. */
export interface SlvsGroupReport {
  group: GroupId;
  name: string;
  kind: string;
  ok: boolean;
  result: string;
  dof: number | null;
  failed: CoreConstraintId[];
}

/** The model as JSON: parameters, entities, constraints. */
export interface ModelJson {
  params: { h: ParamId; group: GroupId; val: number }[];
  entities: EntityJson[];
  constraints: ConstraintJson[];
}

export class System {
  /** An empty system. */
  constructor();
  /** Reads a loci JSON problem file. Throws FormatError or ModelError naming the object. */
  static fromJson(text: string): System;
  /** Reads a SolveSpace `.slvs` file. Throws FormatError with the line at fault. */
  static fromSlvs(bytes: Uint8Array): System;
  /** The loci JSON problem file. */
  toJson(): string;
  /** The `.slvs` file: the one read with the new values, or a new one SolveSpace opens. */
  toSlvs(): Uint8Array;
  model(): ModelJson;
  addParam(h: number, group: GroupId, value: number): ParamId;
  addEntity(entity: EntityJson): EntityId;
  addConstraint(constraint: ConstraintJson): CoreConstraintId;
  removeConstraint(h: CoreConstraintId): boolean;
  value(h: ParamId): number | undefined;
  setValue(h: ParamId, value: number): boolean;
  /** Every parameter's handle, in the order of `values()`. */
  paramHandles(): Uint32Array;
  /** Every parameter's value, in the order of `paramHandles()`. */
  values(): Float64Array;
  setValues(values: Float64Array | number[]): void;
  groups(): GroupId[];
  /** Solves one group; parameter values change only when the outcome is okay. */
  solve(group: GroupId, options?: SolveOptions): SolveReport;
  /** Solves as the file's `solve` request says (or the highest group with constraints). */
  solveRequest(): SolveReport;
  /** Solves every group of a `.slvs` file in order, as SolveSpace does. */
  solveAll(): SlvsGroupReport[];
  check(group: GroupId): Diagnosis;
  /** Frees the WebAssembly memory now rather than when collected. */
  free(): void;
}

// ---------------------------------------------------------------------------------------------
// The sketcher

export type PointId = Handle<"PointId">;
export type LineId = Handle<"LineId">;
export type CircleId = Handle<"CircleId">;
export type ArcId = Handle<"ArcId">;
export type CubicId = Handle<"CubicId">;
export type ShapeId = PointId | LineId | CircleId | ArcId | CubicId;
/** A circle or an arc. */
export type RoundId = CircleId | ArcId;
export type SketchConstraintId = Handle<"SketchConstraintId">;

export type ShapeKind = "point" | "line" | "circle" | "arc" | "cubic";
export type End = "start" | "end";
export type Axis = "horizontal" | "vertical";

/** A user constraint (docs/sketch-format.md), naming shapes by handle. Distances in model
 * units, angles in degrees. */
export type ConstraintSpec =
  | { type: "fix"; point: PointId }
  | { type: "fix_shape"; shape: ShapeId }
  | { type: "length"; line: LineId; value: number }
  | { type: "horizontal"; line: LineId }
  | { type: "vertical"; line: LineId }
  | { type: "radius"; shape: RoundId; value: number }
  | { type: "diameter"; shape: RoundId; value: number }
  | { type: "arc_sweep"; arc: ArcId; degrees: number }
  | { type: "lock"; shape: LineId | RoundId }
  | { type: "distance"; a: PointId; b: PointId; value: number }
  | { type: "coincident"; a: PointId; b: PointId }
  | { type: "concentric"; a: RoundId; b: RoundId }
  | { type: "parallel"; a: LineId; b: LineId }
  | { type: "perpendicular"; a: LineId; b: LineId }
  | { type: "angle"; a: LineId; b: LineId; degrees: number }
  | { type: "equal_length"; a: LineId; b: LineId }
  | { type: "equal_radius"; a: RoundId; b: RoundId }
  | { type: "tangent"; a: LineId | RoundId; b: LineId | RoundId; a_end?: End; b_end?: End }
  | { type: "point_on_line"; point: PointId; line: LineId }
  | { type: "point_on_circle"; point: PointId; shape: RoundId }
  | { type: "midpoint"; point: PointId; line: LineId }
  | { type: "symmetric"; a: PointId; b: PointId; line: LineId }
  | { type: "symmetric_axis"; a: PointId; b: PointId; axis: Axis }
  | { type: "point_line_distance"; point: PointId; line: LineId; value: number }
  | { type: "collinear"; a: LineId; b: LineId };

/** Every kind of user constraint. */
export type ConstraintType = ConstraintSpec["type"];

/** A shape as listed: its defining points in order (a line's start and end; a circle's
 * centre; an arc's centre, start and end; a cubic's four control points). */
export type ShapeInfo =
  | { kind: "point"; id: PointId; name: string; construction: boolean; points: [] }
  | { kind: "line"; id: LineId; name: string; construction: boolean; points: [PointId, PointId] }
  | { kind: "circle"; id: CircleId; name: string; construction: boolean; points: [PointId] }
  | { kind: "arc"; id: ArcId; name: string; construction: boolean; points: [PointId, PointId, PointId] }
  | { kind: "cubic"; id: CubicId; name: string; construction: boolean; points: [PointId, PointId, PointId, PointId] };

export interface ConstraintInfo {
  id: SketchConstraintId;
  /** Its name from the file, or its kind and handle. */
  name: string;
  reference: boolean;
  spec: ConstraintSpec;
}

/** A soft constraint: what a solve or drag keeps unless it stands in the way. */
export type Soft =
  | { keeps: "line_length"; shape: LineId }
  | { keeps: "arc_radius"; shape: ArcId }
  | { keeps: "arc_start"; shape: ArcId }
  | { keeps: "arc_end"; shape: ArcId };

export interface SketchReport {
  outcome: Outcome;
  /** User constraints named redundant, conflicting or unsatisfied, in the order added. */
  failed: SketchConstraintId[];
  /** Their names, in the same order. */
  failed_names: string[];
  kept: Soft[];
  dropped: Soft[];
  iterations: number;
  residual: number;
}

export interface SketchCheck {
  outcome: Outcome;
  dof: number;
  /** Minimal sets of user constraints that cannot all hold. */
  conflicting: SketchConstraintId[][];
  /** Sets of user constraints some of which are redundant. */
  redundant: SketchConstraintId[][];
  /** The name of every constraint in a conflict or redundancy, by handle. */
  names: Record<number, string>;
  /** Shapes that can still move, with their degrees of freedom. */
  free: { shape: ShapeId; dof: number }[];
  /** Shapes that cannot move: fully constrained. */
  fixed: ShapeId[];
}

export interface DragStep {
  outcome: Outcome;
  /** Whether the whole step was taken (else the grip went toward the cursor as far as the constraints let it). */
  reached: boolean;
  pieces: number;
  refused: number;
  /** Pieces undone because they would have turned a triangle, a hinge's bend, an arc or a tangency over. */
  flips_prevented: number;
  /** Where the dragged shape's grip ended. */
  at: [number, number];
  miss: number;
}

export interface Measured {
  value: number | null;
  residual: number;
}

export class Sketch {
  /** An empty sketch in the xy plane. */
  constructor();
  /** Reads a sketch file. Throws FormatError or SketchError naming the shape or constraint. */
  static fromJson(text: string): Sketch;
  /** The sketch file with the current coordinates and names. */
  toJson(): string;
  /** The sketch's system as a new `.slvs` file SolveSpace opens. */
  toSlvs(): Uint8Array;
  /** The sketch's system as a loci JSON problem. */
  toProblemJson(): string;
  addPoint(x: number, y: number, name?: string): PointId;
  addLine(a: PointId, b: PointId, name?: string): LineId;
  addCircle(center: PointId, radius: number, name?: string): CircleId;
  /** An arc counter-clockwise from `start` to `end` about `center`. */
  addArc(center: PointId, start: PointId, end: PointId, name?: string): ArcId;
  setConstruction(shape: ShapeId, on: boolean): void;
  /** Removes a shape, the shapes built on it and the constraints on them. */
  removeShape(shape: ShapeId): { shapes: ShapeId[]; constraints: SketchConstraintId[] };
  movePoint(point: PointId, x: number, y: number): void;
  addConstraint(spec: ConstraintSpec, options?: { reference?: boolean; name?: string }): SketchConstraintId;
  removeConstraint(id: SketchConstraintId): void;
  setValue(id: SketchConstraintId, value: number): void;
  measure(id: SketchConstraintId): Measured;
  /** Solves with soft constraints. */
  solve(): SketchReport;
  /** Degrees of freedom, conflicts and redundancies, free and fixed shapes. */
  check(): SketchCheck;
  shapes(): ShapeInfo[];
  constraints(): ConstraintInfo[];
  softConstraints(): Soft[];
  /** Every shape's geometry packed in the order of `shapes()`: a point's x, y; a line's two
   * ends; a circle's centre and radius; an arc's centre, start and end; a cubic's four points. */
  geometry(): Float64Array;
  point(p: PointId): [number, number];
  radius(shape: RoundId): number;
  lineLength(line: LineId): number;
  /** Starts dragging a point, or a whole line, circle or arc (ending a drag in progress). */
  beginDrag(shape: ShapeId): void;
  /** Drags the grip toward a target: as far as the constraints allow, never flipping. */
  dragTo(x: number, y: number): DragStep;
  /** Ends the drag (any edit ends it too). */
  endDrag(): void;
  readonly dragging: boolean;
  free(): void;
}

// ---------------------------------------------------------------------------------------------
// Assemblies

export type Vec3 = [number, number, number];
/** A unit quaternion [w, x, y, z]. */
export type Quat = [number, number, number, number];
export interface Pose {
  translation: Vec3;
  rotation: Quat;
}

export type Reference =
  | { type: "face"; point: Vec3; normal: Vec3 }
  | { type: "edge"; point: Vec3; direction: Vec3 }
  | { type: "circular_edge"; center: Vec3; axis: Vec3; radius: number }
  | { type: "vertex"; point: Vec3 }
  | { type: "axis"; point: Vec3; direction: Vec3 }
  | { type: "frame" };

export interface ComponentJson {
  name: string;
  pose?: Pose;
  grounded?: boolean;
  references?: Record<string, Reference>;
}

/** A reference picked for a mate: of a component, or of the world when `component` is absent. */
export interface Selection {
  component?: string;
  reference: string;
}

export type MateKindJson =
  | { type: "fixed" }
  | { type: "coincident" }
  | { type: "distance"; value: number }
  | { type: "parallel" }
  | { type: "perpendicular" }
  | { type: "angle"; degrees: number }
  | { type: "touch_align" }
  | { type: "concentric" }
  | { type: "fastened" }
  | { type: "revolute" }
  | { type: "slider" }
  | { type: "cylindrical" }
  | { type: "ball" }
  | { type: "planar" }
  | { type: "pin_slot" };
export type MateType = MateKindJson["type"];

export type MateJson = MateKindJson & {
  id?: string;
  a: Selection;
  b: Selection;
  flip?: boolean;
  limits?: [number, number];
};

export type MateStatus =
  | "satisfied" | "adjusted" | "blocked" | "invalid_selection" | "no_direction"
  | "same_component" | "not_attached" | "redundant" | "conflicting" | "unsatisfied";

export interface MateReport {
  id: string;
  kind: MateType;
  status: MateStatus;
  value?: number;
  error: number;
  message?: string;
  limit_violated?: boolean;
}

export interface ComponentReport {
  name: string;
  grounded: boolean;
  pose: Pose;
  /** Independent motions left (0: held); `null` when not computed (`diagnose: false`). */
  dof: number | null;
  /** Those motions in words; empty when `dof` is `null`. */
  motions: string[];
}

export interface AssemblyReport {
  outcome: Outcome;
  dof: number;
  iterations: number;
  residual: number;
  mates: MateReport[];
  components: ComponentReport[];
  /** Minimal sets of mate ids that cannot all hold. */
  conflicts: string[][];
  redundant: string[][];
}

export interface SteppedRun {
  iterations: { index: number; poses: Pose[]; errors: number[] }[];
  converged: boolean;
}

export interface AngleReading {
  angle: number;
  angle_deg: number;
  signed: number;
  signed_deg: number;
  error: number;
  [more: string]: unknown;
}

export class Assembly {
  /** An empty assembly. */
  constructor();
  /** Reads an assembly file (`loci_assembly`). Throws FormatError or AssemblyError. */
  static fromJson(text: string): Assembly;
  toJson(): string;
  /** Adds a component; its index. */
  addComponent(component: ComponentJson): number;
  /** Adds a mate; its id (given one when it has none). */
  addMate(mate: MateJson): string;
  /** Solves every mate at once. */
  solve(): AssemblyReport;
  /** One mate at a time, pass after pass, for animation. */
  solveStepped(): SteppedRun;
  componentNames(): string[];
  components(): ComponentJson[];
  /** Seven numbers per component in `componentNames()` order: x, y, z, then w, qx, qy, qz. */
  poses(): Float64Array;
  setPose(component: string, pose: Float64Array | number[]): void;
  measureAngle(id: string): AngleReading | null;
  free(): void;
}

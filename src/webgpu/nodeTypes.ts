/** The TSL node types the WebGPU Ocean's materials pass between their functions, by what they hold. */
import type { Node } from 'three/webgpu';

export type FloatNode = Node<'float'>;
export type IntNode = Node<'int'>;
export type UintNode = Node<'uint'>;
export type Vec2Node = Node<'vec2'>;
export type Vec3Node = Node<'vec3'>;
export type Vec4Node = Node<'vec4'>;

import { BoxGeometry, BufferGeometry, Camera, Color, Group, InstancedMesh, Layers, Mesh, MeshStandardMaterial, Object3D, Scene, ShaderMaterial, type WebGLRenderer, type WebGLRenderTarget } from 'three';
import { describe, expect, test } from 'vitest';
import { addSea, captureChanges, hiddenSeaObjects, holdsOnlySeas, removeSea, renderSceneWithoutSea, setCaptureStandIn } from '../../src/render/sceneCapture';

// The one list of sea objects every scene capture hides (src/render/sceneCapture.ts): the same
// list from render to render (nothing made per frame), made again when a sea comes, grows or goes.

describe('the seas every capture hides', () => {
  test('one list for every sea, kept between renders and made again when a sea is added, grows or is removed', () => {
    const first = { objects: [new Mesh(), new Object3D()] as Object3D[] };
    const second = { objects: [new Mesh()] as Object3D[] };
    addSea(first, first.objects);
    const once = hiddenSeaObjects();
    expect(hiddenSeaObjects()).toBe(once);
    expect(once.list).toEqual(first.objects);
    addSea(second, second.objects);
    const both = hiddenSeaObjects();
    expect(both).not.toBe(once);
    expect([...both.set]).toEqual([...first.objects, ...second.objects]);
    const sky = new Object3D();
    second.objects.push(sky);
    addSea(second, second.objects);
    expect(hiddenSeaObjects().set.has(sky)).toBe(true);
    removeSea(first);
    expect(hiddenSeaObjects().list).toEqual(second.objects);
    removeSea(second);
    expect(hiddenSeaObjects().list).toEqual([]);
  });

  test('a scene holds only seas when every object in it is a sea or a group of them', () => {
    const sea = { objects: [new Mesh(), new Object3D()] };
    addSea(sea, sea.objects);
    const scene = new Scene();
    const ocean = new Group();
    ocean.add(...sea.objects);
    scene.add(ocean);
    expect(holdsOnlySeas(scene)).toBe(true);
    const box = new Mesh();
    scene.add(box);
    expect(holdsOnlySeas(scene)).toBe(false);
    scene.remove(box);
    expect(holdsOnlySeas(scene)).toBe(true);
    removeSea(sea);
    expect(holdsOnlySeas(scene)).toBe(false);
  });
});

// The reflection's near plane is horizontal, at the water or down at its troughs (sceneReflection.ts):
// a mesh whose vertices all lie under it is clipped whole there, so its capture leaves it out.
// Only meshes whose vertices are where their geometry's bounding box says are judged.
describe('the meshes the reflection leaves out: wholly under the water', () => {
  test('a box whose top is under y = 0 is left out; one reaching above, and any whose vertices may move, are kept', () => {
    const scene = new Scene();
    const box = new BoxGeometry(2, 2, 2); // y from −1 to 1 about its centre
    const material = new MeshStandardMaterial();
    const placed = (y: number, mesh: Mesh = new Mesh(box, material)) => {
      mesh.position.y = y;
      scene.add(mesh);
      return mesh;
    };
    const sunk = placed(-1.01); // top at −0.01
    placed(-0.99); // top at +0.01
    const turned = placed(-1.01);
    turned.rotation.x = Math.PI / 4; // its corners reach −1.01 + √2 > 0
    placed(-5, new Mesh(box, new ShaderMaterial())); // a vertex shader of its own may move it
    placed(-5, new InstancedMesh(box, material, 1)); // its instances are elsewhere
    const child = new Mesh(box, material);
    placed(-5).add(child); // a parent is kept (hidden, it would hide a child that may reach above); its sunk child is not
    placed(-5).visible = false; // not drawn anyway
    const inGroup = new Mesh(box, material);
    const group = new Group();
    group.position.y = -3;
    group.add(inGroup);
    scene.add(group);
    scene.updateMatrixWorld();
    const out: Object3D[] = [];
    captureChanges(scene, 0, out, []);
    expect(out.map((o) => o.id)).toEqual([sunk, child, inGroup].map((o) => o.id));
    // Under a plane 1.5 m down (a rough sea's troughs), the box sunk 1 cm reaches above it and is kept.
    const underTroughs: Object3D[] = [];
    captureChanges(scene, -1.5, underTroughs, []);
    expect(underTroughs.map((o) => o.id)).toEqual([child, inGroup].map((o) => o.id));
  });
});

// A stand-in (setCaptureStandIn) is drawn in the captures only: the render sees it in the mesh's
// place, and the mesh has its own geometry again after (a renderer that records what it draws).
describe('capture stand-ins', () => {
  test('a mesh with a stand-in is drawn with it in a capture and gets its own geometry back; a hidden one is not swapped', () => {
    const scene = new Scene();
    const material = new MeshStandardMaterial();
    const own = new BoxGeometry(1, 1, 1);
    const coarse = new BufferGeometry();
    const standing = new Mesh(own, material);
    const sunk = new Mesh(own, material);
    sunk.position.y = -5;
    const plain = new Mesh(own, material);
    scene.add(standing, sunk, plain);
    scene.updateMatrixWorld();
    setCaptureStandIn(standing, coarse);
    setCaptureStandIn(sunk, coarse);
    const hide: Object3D[] = [];
    const swap: Mesh[] = [];
    captureChanges(scene, 0, hide, swap);
    expect(hide).toEqual([sunk]);
    expect(swap).toEqual([standing]);

    const drawn: BufferGeometry[][] = [];
    const renderer = {
      getRenderTarget: () => null,
      getActiveCubeFace: () => 0,
      getActiveMipmapLevel: () => 0,
      getClearColor: (colour: Color) => colour,
      getClearAlpha: () => 1,
      setRenderTarget: () => undefined,
      setClearColor: () => undefined,
      clear: () => undefined,
      autoClear: true,
      xr: { enabled: false },
      shadowMap: { autoUpdate: true },
      state: { buffers: { depth: { setMask: () => undefined } } },
      render: () => drawn.push([standing, sunk, plain].map((m) => m.geometry)),
    } as unknown as WebGLRenderer;
    const layers = new Layers();
    renderSceneWithoutSea(renderer, scene, new Camera(), {} as WebGLRenderTarget, layers);
    expect(drawn).toEqual([[coarse, coarse, own]]); // no near plane: nothing hidden, both stand in
    expect([standing, sunk, plain].map((m) => m.geometry)).toEqual([own, own, own]);
    setCaptureStandIn(standing, null);
    renderSceneWithoutSea(renderer, scene, new Camera(), {} as WebGLRenderTarget, layers);
    expect(drawn[1]).toEqual([own, coarse, own]);
    expect(standing.geometry).toBe(own);
  });
});

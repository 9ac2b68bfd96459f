import { Group, Mesh, Object3D, Scene } from 'three';
import { describe, expect, test } from 'vitest';
import { addSea, hiddenSeaObjects, holdsOnlySeas, removeSea } from '../../src/render/sceneCapture';

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

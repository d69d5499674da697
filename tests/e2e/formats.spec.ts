/**
 * More formats, as a user meets them: a PLY and an STL dropped on the app
 * give their counts, a PNG dropped by mistake is named as a PNG with the
 * previous mesh kept, binary bytes or a binary STL named .off are named as
 * such rather than quoted, a cube with one face flipped offers "Repair
 * orientation", and the Export menu's PLY and STL files hold the shown
 * level with a comment naming model, scheme and level.
 */
import { readFile } from 'node:fs/promises';
import { join } from 'node:path';
import { expect, test } from './fixtures';

const fixture = (name: string) => readFile(join('tests', 'fixtures', name));

test('PLY and STL dropped give their counts; a PNG is named and the mesh stays', async ({ app }) => {
  await app.open();

  await test.step('a binary big-endian PLY cube: 8 vertices, 12 edges, 6 quads', async () => {
    await app.load('cube-be.ply', await fixture('cube-be.ply'));
    expect(await app.facts()).toMatchObject({ vertices: 8, edges: 12, faces: 6, genus: 0, boundaries: 0 });
  });

  await test.step('a binary STL tetrahedron (header starting with "solid"): 12 corners welded to 4 vertices', async () => {
    await app.load('tetrahedron-binary.stl', await fixture('tetrahedron-binary.stl'));
    expect(await app.facts()).toMatchObject({ vertices: 4, edges: 6, faces: 4, genus: 0 });
    await app.subdivide();
    expect(await app.facts()).toMatchObject({ vertices: 14, edges: 24, faces: 12 });
  });

  await test.step('a PNG: "This is a PNG image", the tetrahedron and its level stay', async () => {
    await app.dropFile('photo.png', await fixture('not-a-mesh.png'));
    await expect(app.byTestId('error.message')).toHaveText(
      'This is a PNG image, not a mesh. SubdivLab reads OFF, OBJ, PLY and STL.',
    );
    await expect(app.byTestId('error.source')).toContainText('photo.png');
    await expect(app.byTestId('facts.model')).toHaveText('tetrahedron-binary.stl');
    expect((await app.state()).level).toBe(1);
    await app.snapshot('formats-png-refused');
  });

  await test.step('binary bytes named .off, a binary STL named .off: named, no bytes quoted', async () => {
    // Every byte value once: 28 control bytes and 128 in no UTF-8 sequence.
    await app.dropFile('scan.off', Buffer.from(Array.from({ length: 256 }, (_, i) => i)));
    await expect(app.byTestId('error.message')).toHaveText(
      'This looks like a binary file, not OFF text: 156 of its first 256 bytes are control bytes or no UTF-8 text. SubdivLab reads OFF, OBJ, PLY and STL.',
    );
    await expect(app.byTestId('error.source')).toContainText('scan.off');
    await app.snapshot('formats-binary-refused');
    await app.dropFile('part.off', await fixture('tetrahedron-binary.stl'));
    await expect(app.byTestId('error.message')).toHaveText(
      'This looks like a binary STL file, not OFF text: give it the .stl extension to read it as STL.',
    );
    await expect(app.byTestId('facts.model')).toHaveText('tetrahedron-binary.stl');
  });

  await test.step('an ASCII STL clears the message', async () => {
    await app.load('tetrahedron.stl', await fixture('tetrahedron.stl'));
    await expect(app.byTestId('error.banner')).toBeHidden();
    expect(await app.facts()).toMatchObject({ vertices: 4, edges: 6, faces: 4 });
  });
});

test('a cube with one face flipped: the error offers "Repair orientation", which loads it repaired', async ({
  app,
}) => {
  await app.open();
  await app.dropFile('cube-flipped-face.off', await fixture('cube-flipped-face.off'));
  await expect(app.byTestId('error.message')).toContainText(
    'inconsistent orientation: the faces on lines 12 and 13 both use edge 2→0 in the same direction; ' +
      'turning 1 face around makes them agree',
  );
  await app.snapshot('formats-orientation-offer');
  await app.byTestId('error.action').click();
  await expect(app.byTestId('facts.model')).toHaveText('cube-flipped-face.off');
  expect(await app.facts()).toMatchObject({ vertices: 8, edges: 12, faces: 6, genus: 0 });
  await expect(app.byTestId('notice.message')).toHaveText(
    'cube-flipped-face.off: orientation repaired: 1 face was reversed to agree with their neighbours.',
  );
  await expect(app.byTestId('error.banner')).toBeHidden();

  await test.step('a Möbius strip is called non-orientable, with no repair offered', async () => {
    await app.dropFile('moebius.off', await fixture('moebius.off'));
    await expect(app.byTestId('error.message')).toContainText(
      'line 18: the surface is non-orientable (like a Möbius strip)',
    );
    await expect(app.byTestId('error.action')).toHaveCount(0);
  });
});

test('Export PLY and STL: the shown level, with the comment naming model, scheme and level', async ({ app }) => {
  await app.open();
  await app.load('cube.ply', await fixture('cube.ply'));
  await app.subdivide();

  await app.byTestId('export-panel').locator('summary').click();
  await app.snapshot('formats-export-menu');
  const ply = await app.download('export.ply');
  expect(ply.suggestedFilename()).toBe('cube-catmull-clark-L1.ply');
  const plyLines = (await readFile(await ply.path(), 'utf8')).split('\n');
  expect(plyLines.slice(0, 4)).toEqual([
    'ply',
    'format ascii 1.0',
    'comment SubdivLab: cube.ply, Catmull-Clark, level 1',
    'element vertex 26',
  ]);
  expect(plyLines).toContain('element face 24');

  await app.byTestId('export-panel').locator('summary').click();
  const stl = await app.download('export.stl');
  expect(stl.suggestedFilename()).toBe('cube-catmull-clark-L1.stl');
  const bytes = await readFile(await stl.path());
  // 24 quads as 48 triangles of 50 bytes after the 80-byte header and the count.
  expect(bytes.length).toBe(84 + 48 * 50);
  expect(bytes.readUInt32LE(80)).toBe(48);
  expect(bytes.subarray(0, 40).toString('latin1')).toBe('SubdivLab: cube.ply, Catmull-Clark, leve');

  await test.step('the STL dropped back: 26 vertices, 48 triangles', async () => {
    await app.load('cube-catmull-clark-L1.stl', bytes);
    expect(await app.facts()).toMatchObject({ vertices: 26, faces: 48, genus: 0 });
  });

  await test.step('OFF carries its comment line too', async () => {
    await app.byTestId('export-panel').locator('summary').click();
    const off = await readFile(await (await app.download('export.off')).path(), 'utf8');
    expect(off.split('\n').slice(0, 2)).toEqual([
      'OFF',
      '# SubdivLab: cube-catmull-clark-L1.stl, Catmull-Clark, level 0',
    ]);
  });
});

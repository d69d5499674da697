/**
 * Check a result: a student's Catmull-Clark level 2 of the cube, made by an
 * independent implementation (tests/unit/reference-subdivision.ts) and
 * written in its own vertex order, is a match; with one vertex moved it is a
 * mismatch naming that vertex, the surface coloured by the errors, and its
 * expected stencil one click away.
 */
import { readFileSync } from 'node:fs';
import { catmullClarkStep, repeat } from '../unit/reference-subdivision';
import type { PlainMesh } from '../unit/test-helpers';
import { expect, test } from './fixtures';

const CUBE = readFileSync('tests/fixtures/cube.off', 'utf8');

/** The cube as plain arrays: the lines after "OFF" and the counts. */
function plainCube(): PlainMesh {
  const lines = CUBE.split('\n').filter((line) => line.trim() !== '' && !line.startsWith('#'));
  const numbers = (line: string) => line.trim().split(/\s+/).map(Number);
  return {
    points: lines.slice(2, 10).map((line) => numbers(line) as [number, number, number]),
    faces: lines.slice(10, 16).map((line) => numbers(line).slice(1)),
  };
}

/**
 * OBJ text of the vertices in reverse order, with comments and blank lines among them, and the line each vertex
 * was written on (1-based), as the test knows it.
 */
function reversedObj(mesh: PlainMesh): { text: string; lineOf: number[] } {
  const n = mesh.points.length;
  const lines = ['# my Catmull-Clark, level 2', '', 'o cube'];
  const lineOf: number[] = [];
  [...mesh.points].reverse().forEach((p, v) => {
    if (v % 10 === 0) lines.push('', `# vertices ${v} to ${v + 9}`);
    lines.push(`v ${p.join(' ')}`);
    lineOf.push(lines.length);
  });
  for (const f of mesh.faces) lines.push(`f ${f.map((v) => n - v).join(' ')}`);
  return { text: `${lines.join('\n')}\n`, lineOf };
}

/** OFF text with the vertices written in reverse order, as another program might. */
function reversedOff(mesh: PlainMesh): string {
  const n = mesh.points.length;
  const lines = ['OFF', `${n} ${mesh.faces.length} 0`, ...[...mesh.points].reverse().map((p) => p.join(' '))];
  for (const f of mesh.faces) lines.push(`${f.length} ${f.map((v) => n - 1 - v).join(' ')}`);
  return `${lines.join('\n')}\n`;
}

test("a student's Catmull-Clark level 2: a match, then one moved vertex named, coloured and its stencil shown", async ({
  app,
}) => {
  await app.open();
  await app.load('cube.off', CUBE);
  const level2 = repeat(catmullClarkStep, plainCube(), 2);
  await app.byTestId('check.level').fill('2');
  await app.byTestId('check.file').setInputFiles({
    name: 'my-cc2.off',
    mimeType: 'text/plain',
    buffer: Buffer.from(reversedOff(level2)),
  });
  await app.byTestId('check.run').click();
  await expect(app.byTestId('check.verdict')).toHaveText('✓ my-cc2.off is level 2.');
  await expect(app.byTestId('check.summary')).toContainText('vertices matched to the nearest');
  // The app computed levels 1 and 2 to check against, and shows level 2.
  expect(await app.state()).toMatchObject({ level: 2, levelCount: 3 });

  const n = level2.points.length;
  const moved = structuredClone(level2);
  moved.points[n - 1 - 30][0] += 0.1;
  await app.byTestId('check.file').setInputFiles({
    name: 'my-cc2-moved.off',
    mimeType: 'text/plain',
    buffer: Buffer.from(reversedOff(moved)),
  });
  const plain = await app.canvasPixels();
  await app.byTestId('check.run').click();
  await expect(app.byTestId('check.verdict')).toHaveText('✗ my-cc2-moved.off is not level 2.');
  await expect(app.byTestId('check.reasons')).toHaveText(
    '1 vertex of 98 is farther from the reference than the tolerance',
  );
  await expect(app.byTestId('check.worst').locator('li')).toHaveCount(1);
  // Vertex 30 of the file is on line 33: after "OFF" and the counts, one vertex a line.
  await expect(app.byTestId('check.worst').locator('li').first()).toContainText('Your vertex 30 (line 33): 0.100 off');
  await expect.poll(async () => (await app.canvasPixels()).equals(plain)).toBe(false);
  await app.snapshot('check-result-mismatch');
  await app.byTestId('check.worst').getByRole('button', { name: 'its stencil' }).click();
  await expect(app.byTestId('stencils.inspect')).toHaveAttribute('aria-pressed', 'true');
  await expect(app.byTestId('stencils.title')).toHaveText(/^Vertex \d+ of level 2$/);

  await test.step('the same as OBJ, with comments and blank lines: its line and its OBJ number (from 1)', async () => {
    const obj = reversedObj(moved);
    await app.byTestId('check.file').setInputFiles({
      name: 'my-cc2-moved.obj',
      mimeType: 'text/plain',
      buffer: Buffer.from(obj.text),
    });
    await app.byTestId('check.run').click();
    await expect(app.byTestId('check.verdict')).toHaveText('✗ my-cc2-moved.obj is not level 2.');
    expect(obj.lineOf[30]).toBe(42);
    await expect(app.byTestId('check.worst').locator('li').first()).toContainText(
      `Your vertex 30 (line ${obj.lineOf[30]}, OBJ v 31): 0.100 off`,
    );
    await app.panelSnapshot('check-panel', 'check-result-vertex-lines');
  });
});

/** Binary little-endian PLY of `mesh` (double coordinates, uchar counts, int indices), as another program might write it. */
function binaryPly(mesh: PlainMesh): Buffer {
  const header = [
    'ply',
    'format binary_little_endian 1.0',
    `element vertex ${mesh.points.length}`,
    'property double x',
    'property double y',
    'property double z',
    `element face ${mesh.faces.length}`,
    'property list uchar int vertex_indices',
    'end_header',
    '',
  ].join('\n');
  const body = Buffer.alloc(24 * mesh.points.length + mesh.faces.reduce((n, f) => n + 1 + 4 * f.length, 0));
  let at = 0;
  for (const p of mesh.points) for (const x of p) at = body.writeDoubleLE(x, at);
  for (const f of mesh.faces) {
    at = body.writeUInt8(f.length, at);
    for (const v of f) at = body.writeInt32LE(v, at);
  }
  return Buffer.concat([Buffer.from(header, 'ascii'), body]);
}

test("a student's level 1 as a binary PLY is read from its bytes and matches", async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.byTestId('check.level').fill('1');
  await app.byTestId('check.file').setInputFiles({
    name: 'my-cc1.ply',
    mimeType: 'application/octet-stream',
    buffer: binaryPly(repeat(catmullClarkStep, plainCube(), 1)),
  });
  await app.byTestId('check.run').click();
  await expect(app.byTestId('check.verdict')).toHaveText('✓ my-cc1.ply is level 1.');
});

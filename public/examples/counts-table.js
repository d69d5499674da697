// Every viewer's level-change event bubbles up to the document, with the level and its facts.
document.addEventListener('level-change', (event) => {
  const row = document.querySelector(`#counts tr[data-viewer="${event.target.id}"]`);
  if (!row) return;
  const { level, facts } = event.detail;
  const cells = row.querySelectorAll('td');
  [level, facts.vertices, facts.edges, facts.faces, facts.genus].forEach((value, i) => {
    cells[i + 1].textContent = String(value);
  });
});

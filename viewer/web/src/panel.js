// The page's panel: the problem's status, a choice of branch, a slider per parameter of the
// chosen branch with what it moves, and the pose shown.
import { Euler, MathUtils, Matrix4, Vector3 } from 'three';

function element(tag, attributes = {}, text = '') {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, v);
  if (text) e.textContent = text;
  return e;
}

// Four significant digits, trailing zeros of the fraction dropped (1000 stays 1000).
function fmt(x) {
  if (!Number.isFinite(x)) return String(x);
  const s = (Math.abs(x) < 5e-13 ? 0 : x).toPrecision(4);
  return s.includes('.') ? s.replace(/\.?0+(e|$)/, '$1') : s;
}

// Components a millionth of the largest are shown as 0: a direction's rounding, not its meaning.
function vec(v) {
  const big = Math.max(...v.map(Math.abs));
  return '(' + v.map((x) => fmt(Math.abs(x) < 1e-6 * big ? 0 : x)).join(', ') + ')';
}

// What a parameter moves, in world terms (docs/spec.md §2.5 `motion`).
function motionText(p) {
  const m = p.motion || {};
  const parts = [];
  if (m.type === 'rotation') parts.push('turns about ' + vec(m.axis) + ' through ' + vec(m.point));
  else if (m.type === 'screw') parts.push('screws about ' + vec(m.axis) + ' through ' + vec(m.point) + ', pitch ' + fmt(m.pitch));
  else if (m.type === 'translation') parts.push('slides along ' + vec(m.axis));
  if (p.constraint_id) parts.push("the range of '" + p.constraint_id + "'");
  else if (p.constraint >= 0) parts.push('the range of constraint ' + p.constraint);
  return parts.join('; ');
}

export function buildPanel(scene, actions) {
  const degrees = scene.angles === 'deg';
  const angle = (x) => (degrees ? fmt(MathUtils.radToDeg(x)) + '°' : fmt(x) + ' rad');
  const value = (p, x) => (p.kind === 'angle' ? angle(x) : fmt(x));

  const panel = document.getElementById('panel');
  panel.append(element('h1', {}, scene.name || 'relpos'));
  const n = scene.branches.length;
  const status = scene.status + (scene.complete ? ', complete' : '') + ' · ' + n + (n === 1 ? ' branch' : ' branches');
  panel.append(element('div', { class: 'status', id: 'status' }, status));
  if (scene.message) panel.append(element('div', { class: 'message' }, scene.message));

  const list = element('div', { id: 'branches' });
  scene.branches.forEach((b, i) => {
    const label = element('label', { class: 'branch' });
    const radio = element('input', { type: 'radio', name: 'branch', value: String(i), id: 'branch-' + i });
    radio.addEventListener('change', () => actions.select(i));
    const kind = b.exact ? 'exact' : 'certified';
    const hit = b.collision ? (b.collision.nearest_collides ? ' · nearest pose collides' : ' · nearest pose free') : '';
    label.append(radio, element('span', {}, '#' + b.index + ' ' + b.manifold + ' — ' + b.dof + ' DOF, ' + kind + hit));
    list.append(label);
  });
  panel.append(list);

  const sliders = element('div', { id: 'sliders' });
  panel.append(sliders);

  const buttons = element('div', { class: 'buttons' });
  const reset = element('button', { id: 'reset', type: 'button' }, 'nearest pose');
  reset.addEventListener('click', actions.reset);
  const toggle = (id, text, action) => {
    const l = element('label');
    const box = element('input', { type: 'checkbox', id, checked: '' });
    box.addEventListener('change', () => action(box.checked));
    l.append(box, document.createTextNode(' ' + text));
    return l;
  };
  buttons.append(reset, toggle('ghosts', 'samples', actions.showGhosts), toggle('others', 'other branches', actions.showOthers));
  panel.append(buttons);
  const pose = element('pre', { id: 'pose' });
  panel.append(pose);
  const checked = scene.branches.some((b) => b.collision);
  panel.append(element('div', { class: 'legend' }, 'blue: ' + scene.fixed.name + ' (fixed) · orange: ' + scene.mobile.name + ' (mobile) · grey: obstacles, other branches · faint: samples' + (checked ? ' · red: a mesh in collision · green: the nearest collision-free pose' : '')));

  return {
    showBranch(i, theta) {
      document.getElementById('branch-' + i).checked = true;
      sliders.replaceChildren();
      const b = scene.branches[i];
      const model = b.model;
      b.parameters.forEach((p, k) => {
        const row = element('div', { class: 'parameter' });
        const [lo, hi] = model.range[k];
        // A product takes any value in the range; a table only its grid's, so its slider runs over
        // the nodes' indices (a browser would round a value step by step from the minimum).
        const nodes = model.product ? 0 : model.count[k];
        const at = (j) => (j <= 0 ? lo : j >= nodes - 1 ? hi : lo + j * model.step[k]);
        const attributes = nodes
          ? { min: '0', max: String(nodes - 1), step: '1', value: String(Math.round((theta[k] - lo) / (model.step[k] || 1))) }
          : { min: String(lo), max: String(hi), step: 'any', value: String(theta[k]) };
        const input = element('input', { type: 'range', id: 'param-' + k, ...attributes });
        const shown = element('span', { class: 'value', id: 'value-' + k }, value(p, theta[k]));
        input.addEventListener('input', () => {
          const x = nodes ? at(Number(input.value)) : Number(input.value);
          shown.textContent = value(p, x);
          actions.setParameter(k, x);
        });
        row.append(element('div', { class: 'name' }, p.name + ' '), shown, input, element('div', { class: 'motion' }, motionText(p)));
        sliders.append(row);
      });
      if (!model.product && b.parameters.length > 0) sliders.append(element('div', { class: 'note' }, 'This branch is shown on a grid of its parameters: the sliders step through computed poses.'));
    },
    showPose(X) {
      if (!X) {
        pose.textContent = 'no pose here (the branch has none at these parameters)';
        return;
      }
      const t = new Vector3().setFromMatrixPosition(X);
      const e = new Euler().setFromRotationMatrix(new Matrix4().extractRotation(X), 'ZYX');
      pose.textContent = 'position ' + vec([t.x, t.y, t.z]) + '\nrpy ' + [e.x, e.y, e.z].map(angle).join(', ');
    },
  };
}

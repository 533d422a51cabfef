// A branch's pose at parameters θ, from the model relpos writes (relpos/report/pose_model.hpp):
// a product of screws about the nearest pose θ*, X(θ) = Π_k exp(ξ_k·rate_k·(θ_k − θ*_k))·X(θ*)
// (a separable branch's factors turning only the orientation or carrying only a pivot point),
// or a table of poses on a grid of parameter values (the node nearest θ). Plain doubles
// throughout, so the page's pose is the solver's to rounding.
import { Matrix4, Vector3 } from 'three';

// A column-major array of 16 numbers as a Matrix4.
export function matrixOf(array) {
  return new Matrix4().fromArray(array);
}

function exponential(f, x) {
  const axis = new Vector3().fromArray(f.axis);
  if (!f.turn) return new Matrix4().makeTranslation(axis.x * x, axis.y * x, axis.z * x);
  const R = new Matrix4().makeRotationAxis(axis, x);
  const p = new Vector3().fromArray(f.point);
  // Translation p − R·p + pitch·x·axis: the turn leaves the axis in place, then advances along it.
  const t = p.clone().sub(p.clone().applyMatrix4(R)).addScaledVector(axis, f.pitch * x);
  return R.setPosition(t);
}

// The pose of the branch at `theta` (one number per parameter), or null where the branch's code
// could not give one (a table node it threw at).
export function branchPose(branch, theta) {
  const model = branch.model;
  if (model.product) {
    const R = new Matrix4(), P = new Matrix4();
    for (const f of model.factors) {
      const E = exponential(f, f.rate * (theta[f.param] - model.at[f.param]));
      if (f.orients) R.multiply(new Matrix4().extractRotation(E));
      if (f.moves) P.multiply(E);
    }
    // X(θ) = [R·R*, P·(X*·pivot) − R·R*·pivot]: the moving factors carry the pivot.
    const X0 = matrixOf(model.X_at);
    const pivot = new Vector3().fromArray(model.pivot);
    const carried = pivot.clone().applyMatrix4(X0).applyMatrix4(P);
    const X = R.multiply(X0.setPosition(0, 0, 0));
    return X.setPosition(carried.sub(pivot.applyMatrix4(X)));
  }
  let k = 0;
  for (let i = 0; i < branch.parameters.length; ++i) {
    const c = model.count[i];
    let j = c > 1 ? Math.round((theta[i] - model.range[i][0]) / model.step[i]) : 0;
    j = Math.min(Math.max(j, 0), c - 1);
    k = k * c + j;
  }
  const X = model.table[k];
  return X ? matrixOf(X) : null;
}

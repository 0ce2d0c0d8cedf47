#include <ThyrixPro/SpatialAlgebra.h>

#include <cmath>

namespace thyrix {

PlanarTransform PlanarTransform::fromAngleAndOrigin(real theta, Vector2 origin) {
  return {std::cos(theta), std::sin(theta), origin};
}

SymmetricMatrix3 PlanarTransform::transposeCongruence(const SymmetricMatrix3& d) const {
  // Partition X = [1 0; h E] and D = [d00 d0^T; d0 D11] (d0 a 2-vector, D11 2x2). Then
  //   X^T D X = [d00 + 2 d0.h + h^T D11 h,  (d0 + D11 h)^T E;  E^T (d0 + D11 h),  E^T D11 E],
  // written out here so that only the six distinct entries are computed.
  const Vector2 hv = h();
  const Vector2 d0{d.xy, d.xz};
  const Vector2 d11h{d.yy * hv.x + d.yz * hv.y, d.yz * hv.x + d.zz * hv.y};
  const Vector2 g = d0 + d11h;  // D's first column below the diagonal, moved to A's origin
  // E^T D11 E, with E = [c s; -s c]: the columns of D11 E, then E^T applied to them.
  const Vector2 col0{d.yy * c - d.yz * s, d.yz * c - d.zz * s};  // D11 (c, -s)
  const Vector2 col1{d.yy * s + d.yz * c, d.yz * s + d.zz * c};  // D11 (s, c)
  const Vector2 e0 = rotateBack(col0);
  const Vector2 e1 = rotateBack(col1);
  const Vector2 gRow = rotateBack(g);
  SymmetricMatrix3 result;
  result.xx = d.xx + 2 * d0.dot(hv) + hv.dot(d11h);
  result.xy = gRow.x;
  result.xz = gRow.y;
  result.yy = e0.x;
  result.yz = e1.x;
  result.zz = e1.y;
  return result;
}

Matrix3 PlanarTransform::motionMatrix() const {
  const Vector2 hv = h();
  Matrix3 x;
  x.m = {{{1, 0, 0}, {hv.x, c, s}, {hv.y, -s, c}}};
  return x;
}

Matrix3 PlanarTransform::forceMatrix() const {
  // X^-T = [1 -h^T E; 0 E]: the inverse of X is [1 0; -E^T h E^T], transposed.
  const Vector2 hv = h();
  Matrix3 x;
  x.m = {{{1, -(hv.x * c - hv.y * s), -(hv.x * s + hv.y * c)}, {0, c, s}, {0, -s, c}}};
  return x;
}

Vector3 spatialForceInFrame(Vector2 force, Vector2 point, Vector2 frameOrigin, real frameAngle) {
  // The moment about the origin is the same scalar in any axes; only the force turns.
  const real moment = cross(point - frameOrigin, force);
  return forceVector(moment, force.rotated(-frameAngle));
}

}  // namespace thyrix

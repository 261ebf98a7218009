//! Numerical building blocks with no mechanics in them: quadrature, root
//! finding, Brent's minimum, ODE integration (two explicit Runge–Kutta pairs and the implicit Radau IIA), a dense LU over reused storage, a sparse LDLᵀ, an SVD that always returns, and the plane's vector products.

pub mod dop853;
pub mod ldl;
pub mod lu;
pub mod minimum;
pub mod ode;
pub mod plane;
pub mod quadrature;
pub mod radau;
pub mod roots;
pub mod scaled;
pub mod svd;
pub mod tridiagonal;

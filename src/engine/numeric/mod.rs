//! Numerical building blocks with no mechanics in them: quadrature, root
//! finding, ODE integration, a sparse LDLᵀ, and an SVD that always returns.

pub mod ldl;
pub mod ode;
pub mod quadrature;
pub mod roots;
pub mod svd;

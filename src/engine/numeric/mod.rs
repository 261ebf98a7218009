//! Numerical building blocks with no mechanics in them: small dense LU,
//! quadrature, root finding and ODE integration.

pub mod dense;
pub mod ode;
pub mod quadrature;
pub mod roots;

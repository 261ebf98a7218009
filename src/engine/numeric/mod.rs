//! Numerical building blocks with no mechanics in them: quadrature, root
//! finding and ODE integration.

pub mod ode;
pub mod quadrature;
pub mod roots;

//! Section Appendix D (3 bodies, Standard Euler).

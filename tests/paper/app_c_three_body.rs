//! Section Appendix C (3 bodies, False Euler).

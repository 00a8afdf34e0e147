//! Section Appendix B (Source code).

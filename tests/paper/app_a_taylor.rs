//! Section Appendix A (Taylor).

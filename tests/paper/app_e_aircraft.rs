//! Section Appendix E (Aircraft).

//! `Domain`: draws, branches, splits and edges, for every pixel sampler.

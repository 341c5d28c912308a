"""Perception: which predicates of a domain are asked of a vision-language model and with which
questions (perception profiles), what it is asked, how its answers are voted on, and active
perception (paper Sec. IV-B, Algorithm 2)."""

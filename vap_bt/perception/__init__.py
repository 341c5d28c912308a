"""Perception: what a vision-language model is asked, how its answers are voted on, and active
perception (paper Sec. IV-B, Algorithm 2)."""

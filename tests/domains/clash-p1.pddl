(define (problem clash-p1) (:domain clash)
  (:objects cup - cup thing - cup place table - place)
  (:init (at cup table) (at thing table) (free))
  (:goal (and (at cup place) (at thing place))))

; A durative action: refused with the requirement named.
(define (domain dur)
  (:requirements :typing :durative-actions)
  (:types thing)
  (:predicates (done ?t - thing))
  (:durative-action work :parameters (?t - thing) :duration (= ?duration 2)
    :condition (at start (not (done ?t)))
    :effect (at end (done ?t))))

; Action costs read from a static function, (increase (total-cost) (road-length ?from ?to)), as
; IPC 2018's agricola does; its problems (roads-p1) minimize total-cost without (= (total-cost) 0),
; which Fast Downward takes to start at 0.
(define (domain roads)
  (:requirements :strips :typing :action-costs)
  (:types town)
  (:predicates (at ?t - town) (road ?a ?b - town))
  (:functions (road-length ?a ?b - town) - number (total-cost) - number)
  (:action drive
    :parameters (?a ?b - town)
    :precondition (and (at ?a) (road ?a ?b))
    :effect (and (not (at ?a)) (at ?b) (increase (total-cost) (road-length ?a ?b)))))
